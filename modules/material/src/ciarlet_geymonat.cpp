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

MaterialPoint3d CiarletGeymonat::at(const Eigen::Matrix3d& C, bool with_tangent) const {
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
  // CC = 2 dS/dC = 4 [c2 (I x I - sym(I)) + a I3 C^-1 x C^-1 - (a I3 - d) sym(C^-1)], with
  // x = tensor_outer and d(C^-1)/dC = -sym(C^-1) = -symmetric_product(C^-1): written as one pass
  // over the 81 entries, since it runs once per triangle and Newton iteration.
  if (!with_tangent) return p;
  const double c_identity = 4.0 * c2_, c_outer = 4.0 * a_ * I3, c_sym = 2.0 * (a_ * I3 - d);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          const double identity =
              (i == j && k == l) - 0.5 * ((i == k && j == l) + (i == l && j == k));
          p.CC(3 * i + j, 3 * k + l) = c_identity * identity + c_outer * Ci(i, j) * Ci(k, l) -
                                       c_sym * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
        }
  return p;
}

MaterialPoint2d CiarletGeymonat::at_plane_strain(const Eigen::Matrix2d& C,
                                                 bool with_tangent) const {
  // at() with C33 = 1: I1 and I2 gain the out-of-plane 1, C^-1 is block diagonal, and the
  // in-plane blocks of S and CC are the same expressions on the 2x2 C^-1.
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const double I1 = C.trace() + 1.0;
  const double I2 = 0.5 * (I1 * I1 - (C * C).trace() - 1.0);
  const double I3 = C.determinant();
  SIG_VERIFY(I3 > 0.0, "Ciarlet-Geymonat law: det C = " << I3 << " <= 0");
  const Eigen::Matrix2d Ci = C.inverse();
  const double lnI3 = std::log(I3);
  const double d = c1_ + 2.0 * c2_ + a_;

  MaterialPoint2d p;
  p.energy = c1_ * (I1 - 3.0 - lnI3) + c2_ * (I2 - 3.0 - 2.0 * lnI3) + a_ * (I3 - 1.0 - lnI3);
  p.S = 2.0 * (c1_ * (I - Ci) + c2_ * (I1 * I - C - 2.0 * Ci) + a_ * (I3 - 1.0) * Ci);
  if (!with_tangent) return p;
  const double c_identity = 4.0 * c2_, c_outer = 4.0 * a_ * I3, c_sym = 2.0 * (a_ * I3 - d);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) {
          const double identity =
              (i == j && k == l) - 0.5 * ((i == k && j == l) + (i == l && j == k));
          p.CC(2 * i + j, 2 * k + l) = c_identity * identity + c_outer * Ci(i, j) * Ci(k, l) -
                                       c_sym * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
        }
  return p;
}

} // namespace sig
