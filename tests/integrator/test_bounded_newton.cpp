// The condensed contact step's pieces: the semi-smooth Newton of the penalty strategies against
// closed-form solutions, and the contact boundary's geometric gap recovered from the CONT data.
#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "integrator/bounded_newton.hpp"
#include "integrator/dynamic_contact.hpp"
#include "test_bodies.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace sig {
namespace {

// phi(x) = c [x - d]_+ per node: the compliance law, piecewise linear.
NodalForceLaw spring(double c, double d) {
  return [c, d](const Eigen::VectorXd& x, Eigen::VectorXd& force, Eigen::VectorXd& slope) {
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      force[i] = x[i] > d ? c * (x[i] - d) : 0.0;
      slope[i] = x[i] >= d ? c : 0.0;
    }
  };
}

TEST(BoundedNewton, SpringOnTwoCoupledNodesMatchesTheClosedForm) {
  Eigen::Matrix2d A;
  A << 3.0, -1.0, -1.0, 2.0;
  const Eigen::Vector2d x_free(0.5, 0.4);
  const double c = 7.0, d = 0.1;
  const BoundedNewtonResult r =
      bounded_newton(A, x_free, spring(c, d), {}, Eigen::VectorXd(), x_free, 20, 1e-13);
  ASSERT_TRUE(r.converged) << r.failure;
  // Both nodes end beyond d (checked below), so (A + c I) x = A x_free + c d (1, 1).
  const Eigen::Vector2d expected = (A + c * Eigen::Matrix2d::Identity())
                                       .ldlt()
                                       .solve(A * x_free + c * d * Eigen::Vector2d::Ones());
  ASSERT_GT(expected.minCoeff(), d);
  EXPECT_LT((r.x - expected).norm(), 1e-14);
  EXPECT_LT((r.lambda - c * (expected.array() - d).matrix()).norm(), 1e-13);
  EXPECT_LE(r.iterations, 3); // piecewise linear: exact once the branch is right
}

TEST(BoundedNewton, BoundHoldsWithANonNegativeMultiplier) {
  Eigen::Matrix2d A;
  A << 4.0, 1.0, 1.0, 3.0;
  const Eigen::Vector2d x_free(1.0, -0.5);
  const Eigen::Vector2d upper(0.3, 0.3);
  const auto no_force = [](const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::VectorXd& s) {
    f.setZero(x.size());
    s.setZero(x.size());
  };
  const BoundedNewtonResult r =
      bounded_newton(A, x_free, no_force, {1, 1}, upper, x_free, 20, 1e-13);
  ASSERT_TRUE(r.converged) << r.failure;
  // Node 0 on its bound, node 1 free: x1 from row 1 with x0 = 0.3, mu0 from row 0.
  const double x1 = x_free[1] - A(1, 0) * (upper[0] - x_free[0]) / A(1, 1);
  EXPECT_NEAR(r.x[0], upper[0], 1e-15);
  EXPECT_NEAR(r.x[1], x1, 1e-14);
  const double mu0 = -(A(0, 0) * (upper[0] - x_free[0]) + A(0, 1) * (x1 - x_free[1]));
  EXPECT_GT(mu0, 0);
  EXPECT_NEAR(r.lambda[0], mu0, 1e-13);
  EXPECT_NEAR(r.lambda[1], 0.0, 1e-15);
  EXPECT_EQ(r.on_bound, (std::vector<char>{1, 0}));
}

TEST(BoundedNewton, IterationLimitIsAResultNotAnException) {
  Eigen::Matrix2d A = Eigen::Matrix2d::Identity();
  const Eigen::Vector2d x_free(1.0, 1.0);
  BoundedNewtonResult r;
  ASSERT_NO_THROW(r = bounded_newton(A, x_free, spring(1e6, 0.0), {}, Eigen::VectorXd(),
                                     Eigen::Vector2d(-1.0, -1.0), 1, 1e-13));
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.failure.empty());
}

TEST(ContactBoundary, GeometricGapIsTheDistanceAndTheBoundAddsTheExtraGap) {
  Mesh mesh = test::perturbed_rectangle(2.0, 1.0, 6, 3);
  for (Eigen::Vector2d& x : mesh.nodes)
    x.y() += 0.25;
  const LinearSystem system = test::free_body_system(mesh, test::unit_material());
  const ReducedSystem reduced = reduce(system);
  const double extra = 0.01;
  ContactLaw law;
  law.depth = extra;
  const ContactElements elements = build_contact_elements(mesh, 3, HalfPlane({0, 0}, {0, 1}), law);
  const ContactBoundary b = contact_boundary(elements, mesh, reduced);
  ASSERT_EQ(b.size(), 7);
  for (int i = 0; i < b.size(); ++i) {
    EXPECT_NEAR(b.geometric_gap[i], 0.25, 1e-15);
    EXPECT_NEAR(b.bound[i] - b.geometric_gap[i], extra, 1e-15);
  }
  // B u = -n . u: a downward displacement of 0.3 is a normal displacement of 0.3, a
  // penetration of 0.05.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(reduced.num_free());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u(2 * i + 1) = -0.3;
  const Eigen::VectorXd x = b.B * u;
  EXPECT_NEAR(x.minCoeff(), 0.3, 1e-15);
  EXPECT_NEAR(b.penetration(x).maxCoeff(), 0.05, 1e-14);
}

} // namespace
} // namespace sig
