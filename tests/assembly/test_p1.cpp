// P1 kernels against what the continuum says they must be: rigid motions cost no energy, a
// linear field has the energy area * W(eps), masses integrate products of linear functions
// exactly, loads sum to the resultant.
#include "assembly/p1.hpp"
#include "material/hooke.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

namespace sig {
namespace {

Matrix23 some_triangle() {
  Matrix23 x;
  x << 0.1, 1.3, 0.4, //
      0.2, -0.1, 0.9;
  return x;
}

// Nodal values of the displacement u(x) = A x + b.
Vector6d linear_field(const Matrix23& x, const Eigen::Matrix2d& A, const Eigen::Vector2d& b) {
  Vector6d u;
  for (int i = 0; i < 3; ++i)
    u.segment<2>(2 * i) = A * x.col(i) + b;
  return u;
}

TEST(P1, AreaAndGradientsOfALinearFunction) {
  const Matrix23 x = some_triangle();
  EXPECT_NEAR(p1_area(x), 0.5 * (1.2 * 0.7 + 0.3 * 0.3), 1e-15);
  const Matrix23 g = p1_gradients(x);
  // sum_i phi(x_i) grad lambda_i = grad phi for phi = 3 + (2, -5).x
  const Eigen::Vector2d grad(2.0, -5.0);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 3; ++i)
    sum += (3.0 + grad.dot(x.col(i))) * g.col(i);
  EXPECT_LT((sum - grad).norm(), 1e-13);
  EXPECT_LT(g.rowwise().sum().norm(), 1e-13);
}

TEST(P1, StiffnessIsSymmetricWithTheRigidMotionsAsKernel) {
  const Matrix23 x = some_triangle();
  Hooke h;
  h.E = 3.0;
  h.nu = 0.3;
  const Matrix6d K = p1_stiffness(x, h.D(), 1.0);
  EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
  Eigen::Matrix2d rotation;
  rotation << 0, -1, 1, 0;
  for (const Vector6d& rigid :
       {linear_field(x, Eigen::Matrix2d::Zero(), {1, 0}),
        linear_field(x, Eigen::Matrix2d::Zero(), {0, 1}), linear_field(x, rotation, {0, 0})})
    EXPECT_LT((K * rigid).norm(), 1e-13 * K.norm());
  const Vector6d eig = Eigen::SelfAdjointEigenSolver<Matrix6d>(K).eigenvalues();
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(std::abs(eig(k)), 1e-13 * eig(5));
  for (int k = 3; k < 6; ++k)
    EXPECT_GT(eig(k), 1e-3 * eig(5));
}

TEST(P1, EnergyOfALinearFieldIsAreaTimesDensity) {
  const Matrix23 x = some_triangle();
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    Hooke h;
    h.E = 2.0;
    h.nu = 0.35;
    h.plane = plane;
    Eigen::Matrix2d A;
    A << 0.3, -0.2, 0.5, 0.1;
    const Vector6d u = linear_field(x, A, {0.7, -0.4});
    const Eigen::Vector3d eps(A(0, 0), A(1, 1), A(0, 1) + A(1, 0));
    const double thickness = 0.25;
    const double energy = 0.5 * u.dot(p1_stiffness(x, h.D(), thickness) * u);
    EXPECT_NEAR(energy, thickness * p1_area(x) * h.energy_density(eps), 1e-14);
    EXPECT_LT((p1_strain_matrix(p1_gradients(x)) * u - eps).norm(), 1e-14);
  }
}

TEST(P1, ConsistentMassIntegratesProductsOfLinearFunctions) {
  const Matrix23 x = some_triangle();
  const double area = p1_area(x), rho = 2.5, t = 0.5;
  const Matrix6d M = p1_consistent_mass(area, rho, t);
  EXPECT_LT((M - M.transpose()).norm(), 1e-15);
  // Constant unit velocity in each direction: the total mass rho * area * t.
  for (int c = 0; c < 2; ++c) {
    Vector6d e = Vector6d::Zero();
    for (int i = 0; i < 3; ++i)
      e(2 * i + c) = 1.0;
    EXPECT_NEAR(e.dot(M * e), rho * area * t, 1e-14);
    EXPECT_NEAR((M * e).sum(), rho * area * t, 1e-14); // no coupling between components
  }
  // u = (x1, 0): int x1^2 = area/6 (sum x_i^2 + sum_{i<j} x_i x_j).
  Vector6d u = Vector6d::Zero();
  for (int i = 0; i < 3; ++i)
    u(2 * i) = x(0, i);
  const Eigen::Vector3d a = x.row(0);
  const double exact =
      area / 6.0 * (a.squaredNorm() + a(0) * a(1) + a(0) * a(2) + a(1) * a(2)) * rho * t;
  EXPECT_NEAR(u.dot(M * u), exact, 1e-14);
}

TEST(P1, LumpedMassIsTheRowSum) {
  const double area = 0.37, rho = 3.0, t = 2.0;
  const Vector6d lumped = p1_lumped_mass(area, rho, t);
  const Vector6d row_sums = p1_consistent_mass(area, rho, t).rowwise().sum();
  EXPECT_LT((lumped - row_sums).norm(), 1e-15);
}

TEST(P1, LoadsSumToTheResultant) {
  const Eigen::Vector2d a(0.5, 1.0), b(2.0, 3.0), g(-1.5, 4.0);
  const Eigen::Vector4d fe = p1_edge_load(a, b, g, 0.5);
  EXPECT_LT((fe.head<2>() + fe.tail<2>() - g * 2.5 * 0.5).norm(), 1e-14); // |b - a| = 2.5
  EXPECT_LT((fe.head<2>() - fe.tail<2>()).norm(), 1e-15);
  const Vector6d fb = p1_body_load(0.3, {1.0, -2.0}, 2.0);
  EXPECT_NEAR(fb(0) + fb(2) + fb(4), 0.6, 1e-15);
  EXPECT_NEAR(fb(1) + fb(3) + fb(5), -1.2, 1e-15);
}

} // namespace
} // namespace sig
