#include "material/ciarlet_geymonat.hpp"

#include "core/error.hpp"

#include <Eigen/LU>

#include <cmath>

namespace sig {

CiarletGeymonat::CiarletGeymonat(double c1, double c2, double a, PlaneMode plane)
    : HyperelasticLaw(plane), c1_(c1), c2_(c2), a_(a) {
  SIG_VERIFY(c1 > 0.0 && c2 >= 0.0 && a >= 0.0,
             "Ciarlet-Geymonat law needs c1 > 0, c2 >= 0, a >= 0 (got c1 = "
                 << c1 << ", c2 = " << c2 << ", a = " << a << ")");
}

MaterialPoint3d CiarletGeymonat::at(const Eigen::Matrix3d& C) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double I1 = C.trace();
  const double I2 = 0.5 * (I1 * I1 - (C * C).trace());
  const double I3 = C.determinant();
  SIG_VERIFY(I3 > 0.0, "Ciarlet-Geymonat law: det C = " << I3 << " <= 0");
  const Eigen::Matrix3d Ci = C.inverse();
  const double lnI3 = std::log(I3);
  const double d = c1_ + 2.0 * c2_ + a_;

  // Each group vanishes at C = I on its own, so W and S are exactly zero there and lose no
  // digits to cancellation near it: d = c1 + 2 c2 + a is split among the three terms.
  MaterialPoint3d p;
  p.energy = c1_ * (I1 - 3.0 - lnI3) + c2_ * (I2 - 3.0 - 2.0 * lnI3) + a_ * (I3 - 1.0 - lnI3);
  // S = 2 dW/dC with dI1/dC = I, dI2/dC = I1 I - C, dI3/dC = I3 C^-1 (thesis 1.61).
  p.S = 2.0 * (c1_ * (I - Ci) + c2_ * (I1 * I - C - 2.0 * Ci) + a_ * (I3 - 1.0) * Ci);
  // CC = 2 dS/dC, with d(C^-1)/dC = -symmetric_product(C^-1).
  p.CC = 4.0 * (c2_ * (tensor_outer(I, I) - symmetric_product(I)) + a_ * I3 * tensor_outer(Ci, Ci) -
                (a_ * I3 - d) * symmetric_product(Ci));
  return p;
}

} // namespace sig
