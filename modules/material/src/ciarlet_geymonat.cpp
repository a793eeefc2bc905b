#include "material/ciarlet_geymonat.hpp"

#include "core/error.hpp"

#include <Eigen/LU>

#include <cmath>
#include <type_traits>

namespace sig {

CiarletGeymonat::CiarletGeymonat(double c1, double c2, double a, PlaneMode plane)
    : HyperelasticLaw(plane), c1_(c1), c2_(c2), a_(a) {
  SIG_VERIFY(c1 > 0.0 && c2 >= 0.0 && a >= 0.0,
             "Ciarlet-Geymonat law needs c1 > 0, c2 >= 0, a >= 0 (got c1 = "
                 << c1 << ", c2 = " << c2 << ", a = " << a << ")");
}

namespace {

/// W, S and CC at C, a dim x dim block: the whole C in 3D, or plane strain's in-plane block of
/// diag(C, 1). Its C33 = 1 enters I1 and I2; C^-1 is then block diagonal, and the in-plane blocks
/// of S and CC are the 3D expressions on the block's inverse.
template <int dim>
std::conditional_t<dim == 3, MaterialPoint3d, MaterialPoint2d>
law_at(double c1, double c2, double a, const Eigen::Matrix<double, dim, dim>& C,
       bool with_tangent) {
  using Point = std::conditional_t<dim == 3, MaterialPoint3d, MaterialPoint2d>;
  constexpr double c33 = dim == 2 ? 1.0 : 0.0; // the out-of-plane entry left out of C
  using Matrix = Eigen::Matrix<double, dim, dim>;
  const Matrix I = Matrix::Identity();
  const double I1 = C.trace() + c33;
  const double I2 = 0.5 * (I1 * I1 - (C * C).trace() - c33 * c33);
  const double I3 = C.determinant(); // in plane strain det diag(C, 1) = det C
  SIG_VERIFY(I3 > 0.0, "Ciarlet-Geymonat law: det C = " << I3 << " <= 0");
  const Matrix Ci = C.inverse();
  const double lnI3 = std::log(I3);
  const double d = c1 + 2.0 * c2 + a;

  // Each group vanishes at C = I on its own, so W and S are exactly zero there and lose no
  // digits to cancellation near it: d = c1 + 2 c2 + a is split among the three terms.
  Point p;
  p.energy = c1 * (I1 - 3.0 - lnI3) + c2 * (I2 - 3.0 - 2.0 * lnI3) + a * (I3 - 1.0 - lnI3);
  // S = 2 dW/dC with dI1/dC = I, dI2/dC = I1 I - C, dI3/dC = I3 C^-1 (thesis 1.61).
  p.S = 2.0 * (c1 * (I - Ci) + c2 * (I1 * I - C - 2.0 * Ci) + a * (I3 - 1.0) * Ci);
  // CC = 2 dS/dC = 4 [c2 (I x I - sym(I)) + a I3 C^-1 x C^-1 - (a I3 - d) sym(C^-1)], with
  // x = tensor_outer and d(C^-1)/dC = -sym(C^-1) = -symmetric_product(C^-1): written as one pass
  // over the dim^4 entries, since it runs once per triangle and Newton iteration.
  if (!with_tangent) return p;
  const double c_identity = 4.0 * c2, c_outer = 4.0 * a * I3, c_sym = 2.0 * (a * I3 - d);
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      for (int k = 0; k < dim; ++k)
        for (int l = 0; l < dim; ++l) {
          const double identity =
              (i == j && k == l) - 0.5 * ((i == k && j == l) + (i == l && j == k));
          p.CC(dim * i + j, dim * k + l) = c_identity * identity + c_outer * Ci(i, j) * Ci(k, l) -
                                           c_sym * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
        }
  return p;
}

} // namespace

MaterialPoint3d CiarletGeymonat::at(const Eigen::Matrix3d& C, bool with_tangent) const {
  return law_at<3>(c1_, c2_, a_, C, with_tangent);
}

MaterialPoint2d CiarletGeymonat::at_plane_strain(const Eigen::Matrix2d& C,
                                                 bool with_tangent) const {
  return law_at<2>(c1_, c2_, a_, C, with_tangent);
}

} // namespace sig
