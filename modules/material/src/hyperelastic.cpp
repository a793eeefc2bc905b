#include "material/hyperelastic.hpp"

#include "core/error.hpp"

#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace sig {

namespace {

constexpr int in_plane_index[4] = {0, 1, 3, 4}; // 3D index 3 i + J of F11, F12, F21, F22
constexpr int out_of_plane = 8;                 // 3D index of F33

Eigen::Matrix3d embedded(const Eigen::Matrix2d& F, double F33) {
  Eigen::Matrix3d F3 = Eigen::Matrix3d::Zero();
  F3.topLeftCorner<2, 2>() = F;
  F3(2, 2) = F33;
  return F3;
}

// The 3D response at F3 (det > 0) in the 9x9 Voigt form.
struct Response3d {
  double energy;
  Eigen::Matrix3d P;
  Matrix9d A;
};

Response3d response_3d(const HyperelasticLaw& law, const Eigen::Matrix3d& F3) {
  const MaterialPoint3d point = law.at(F3.transpose() * F3);
  return {point.energy, F3 * point.S, first_piola_tangent(F3, point)};
}

void verify_orientation(const Eigen::Matrix2d& F) {
  SIG_VERIFY(F.determinant() > 0.0,
             "hyperelastic law: det F = " << F.determinant() << " <= 0 (inverted element)");
}

} // namespace

Matrix9d tensor_outer(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  Matrix9d T;
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
      for (int K = 0; K < 3; ++K)
        for (int L = 0; L < 3; ++L)
          T(3 * I + J, 3 * K + L) = A(I, J) * B(K, L);
  return T;
}

Matrix9d symmetric_product(const Eigen::Matrix3d& A) {
  Matrix9d T;
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
      for (int K = 0; K < 3; ++K)
        for (int L = 0; L < 3; ++L)
          T(3 * I + J, 3 * K + L) = 0.5 * (A(I, K) * A(J, L) + A(I, L) * A(J, K));
  return T;
}

Matrix9d first_piola_tangent(const Eigen::Matrix3d& F, const MaterialPoint3d& point) {
  // dP = dF S + F dS with dS_IJ = CC_IJKL F_kK dF_kL (CC minor symmetric, dC = dF^T F + F^T dF):
  // A = kron(F, I) CC kron(F, I)^T + kron(I, S). The Kronecker factors are applied as the two
  // index contractions they are (2 x 243 multiply-adds), not as 9 x 9 matrix products: this
  // runs once per triangle and Newton iteration.
  const Matrix9d& CC = point.CC;
  Matrix9d T; // T(3 i + J, 3 K + L) = F_iI CC(3 I + J, 3 K + L)
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int c = 0; c < 9; ++c)
        T(3 * i + J, c) = F(i, 0) * CC(J, c) + F(i, 1) * CC(3 + J, c) + F(i, 2) * CC(6 + J, c);
  Matrix9d A; // A(r, 3 k + L) = T(r, 3 K + L) F_kK
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
      for (int r = 0; r < 9; ++r)
        A(r, 3 * k + L) = T(r, L) * F(k, 0) + T(r, 3 + L) * F(k, 1) + T(r, 6 + L) * F(k, 2);
  for (int i = 0; i < 3; ++i)
    A.block<3, 3>(3 * i, 3 * i) += point.S;
  return A;
}

HyperelasticResponse HyperelasticLaw::response(const Eigen::Matrix2d& F) const {
  verify_orientation(F);
  return plane_ == PlaneMode::strain ? plane_strain(F) : plane_stress(F);
}

HyperelasticResponse HyperelasticLaw::plane_strain(const Eigen::Matrix2d& F) const {
  // F3 = diag(F, 1): only the in-plane entries of first_piola_tangent's A are needed, and for
  // in-plane i, k they contract CC over in-plane I, K alone (F3 has no in-plane row reaching
  // index 3): A(iJ, kL) = F_iI CC(IJ, KL) F_kK + delta_ik S_JL.
  const MaterialPoint2d point = at_plane_strain(F.transpose() * F, true);
  HyperelasticResponse out;
  out.energy = point.energy;
  out.stress = F * point.S;
  // The two contractions one after the other (32 multiply-adds each): T(iJ, KL) = F_iI
  // CC(IJ, KL), then A(iJ, kL) = T(iJ, KL) F_kK.
  Eigen::Matrix4d T;
  for (int i = 0; i < 2; ++i)
    for (int J = 0; J < 2; ++J)
      T.row(2 * i + J) = F(i, 0) * point.CC.row(J) + F(i, 1) * point.CC.row(2 + J);
  for (int k = 0; k < 2; ++k)
    for (int L = 0; L < 2; ++L)
      out.tangent.col(2 * k + L) = T.col(L) * F(k, 0) + T.col(2 + L) * F(k, 1);
  for (int i = 0; i < 2; ++i)
    out.tangent.block<2, 2>(2 * i, 2 * i) += point.S;
  out.stretch33 = 1.0;
  return out;
}

MaterialPoint2d HyperelasticLaw::at_plane_strain(const Eigen::Matrix2d& C,
                                                 bool with_tangent) const {
  const MaterialPoint3d point = at(embedded(C, 1.0), with_tangent);
  MaterialPoint2d out;
  out.energy = point.energy;
  out.S = point.S.topLeftCorner<2, 2>();
  if (!with_tangent) return out;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      out.CC(a, b) = point.CC(in_plane_index[a], in_plane_index[b]);
  return out;
}

HyperelasticResponse HyperelasticLaw::plane_stress(const Eigen::Matrix2d& F) const {
  const double F33 = std::sqrt(out_of_plane_c33(F.transpose() * F));
  const Response3d r = response_3d(*this, embedded(F, F33));
  HyperelasticResponse out;
  out.energy = r.energy;
  out.stress = r.P.topLeftCorner<2, 2>();
  // P33(F, F33(F)) = 0 gives dF33/dF_b = -A_3b / A_33: the static condensation of F33.
  const double A33 = r.A(out_of_plane, out_of_plane);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      out.tangent(a, b) =
          r.A(in_plane_index[a], in_plane_index[b]) -
          r.A(in_plane_index[a], out_of_plane) * r.A(out_of_plane, in_plane_index[b]) / A33;
  out.stretch33 = F33;
  return out;
}

MaterialPoint2d HyperelasticLaw::in_plane(const Eigen::Matrix2d& C, bool with_tangent) const {
  SIG_VERIFY(C.determinant() > 0.0,
             "hyperelastic law: det C = " << C.determinant() << " <= 0 (inverted element)");
  if (plane_ == PlaneMode::strain) return at_plane_strain(C, with_tangent);
  const Eigen::Matrix3d C3 = embedded(C, out_of_plane_c33(C));
  const MaterialPoint3d point = at(C3, with_tangent);
  MaterialPoint2d out;
  out.energy = point.energy;
  out.S = point.S.topLeftCorner<2, 2>();
  if (!with_tangent) return out;
  // Plane stress: S33 = 0 along the path gives dC33 = -CC_33pq dC_pq / CC_3333, which condenses
  // the tangent as for the first Piola tangent in plane_stress().
  const double CC33 = point.CC(out_of_plane, out_of_plane);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      out.CC(a, b) = point.CC(in_plane_index[a], in_plane_index[b]) -
                     point.CC(in_plane_index[a], out_of_plane) *
                         point.CC(out_of_plane, in_plane_index[b]) / CC33;
  return out;
}

double HyperelasticLaw::out_of_plane_c33(const Eigen::Matrix2d& C2) const {
  // S33 increases with C33 (dS33/dC33 = CC_3333 / 2 > 0 for both laws), so the root is kept in a
  // bracket [low, high] updated at each evaluation; a Newton step that leaves the bracket is
  // replaced by bisection (or by halving / doubling while one side is still open).
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C.topLeftCorner<2, 2>() = C2;
  double low = 0.0, high = std::numeric_limits<double>::infinity();
  double x = 1.0;
  constexpr int max_iterations = 200;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    C(2, 2) = x;
    const MaterialPoint3d point = at(C);
    const double residual = point.S(2, 2);
    if (residual == 0.0) return x;
    (residual < 0.0 ? low : high) = x;
    double next = x - residual / (0.5 * point.CC(out_of_plane, out_of_plane));
    if (!(next > low && next < high)) {
      if (std::isinf(high))
        next = 2.0 * x;
      else
        next = 0.5 * (low + high);
    }
    if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * x) return next;
    x = next;
  }
  SIG_VERIFY(false, "plane stress: no out-of-plane stretch with zero stress S33 (bracket ["
                        << low << ", " << high << "] for C33; the in-plane stretch is too large "
                        << "for the law)");
  return x;
}

Hooke HyperelasticLaw::linearized() const {
  const double l = lambda(), m = mu();
  Hooke h;
  h.E = m * (3.0 * l + 2.0 * m) / (l + m);
  h.nu = l / (2.0 * (l + m));
  h.plane = plane_;
  return h;
}

} // namespace sig
