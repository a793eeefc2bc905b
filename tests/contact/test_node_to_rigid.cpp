// The node-to-rigid element kernels: tangent = finite-difference Jacobian of the residual on both
// sides of the contact kink, symmetry of the Alart-Curnier tangent, and the mechanics: at a
// Signorini contact state the element pushes the body along +n with the force lambda.
#include "contact/node_to_rigid.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace sig {
namespace {

const std::vector<Eigen::Vector2d> kNormals = {
    {0, 1}, {1, 0}, Eigen::Vector2d(3, 4).normalized(), Eigen::Vector2d(-1, 0.2).normalized()};

NodeToRigidMatrix finite_difference_jacobian(const NodeToRigidVector& x, const Eigen::Vector2d& n,
                                             double g, double r, double h) {
  NodeToRigidMatrix j;
  for (int k = 0; k < 3; ++k) {
    NodeToRigidVector e = NodeToRigidVector::Zero();
    e(k) = h;
    j.col(k) =
        (alart_curnier_residual(x + e, n, g, r) - alart_curnier_residual(x - e, n, g, r)) / (2 * h);
  }
  return j;
}

TEST(NodeToRigid, AlartCurnierTangentMatchesFiniteDifferences) {
  for (double r : {1e-2, 1.0, 1e2, 1e4})
    for (const auto& n : kNormals)
      for (double g : {0.0, 0.3})
        for (double offset : {1e-6, 1e-4, 1e-2, 1.0})
          for (double side : {-1.0, 1.0}) {
            // A displacement with u_n - g = 0.2 (or -0.2), then lambda so that
            // lambda + r (u_n - g) = side * offset: active (+) or inactive (-) by `offset`.
            const Eigen::Vector2d tangent(-n.y(), n.x());
            const double un = g + (side > 0 ? -0.2 : 0.2);
            const Eigen::Vector2d u = -un * n + 0.7 * tangent;
            NodeToRigidVector x;
            x << u, -r * (un - g) + side * offset;
            // Steps small enough to stay on the same side of the kink in every direction.
            const double h = offset / (8 * std::max(1.0, r));
            const NodeToRigidMatrix fd = finite_difference_jacobian(x, n, g, r, h);
            const NodeToRigidMatrix t = alart_curnier_tangent(x, n, g, r);
            const double scale = 1 + r + std::abs(x(2));
            EXPECT_LE((t - fd).cwiseAbs().maxCoeff(), 1e-7 * (1 + r) + 2e-15 * scale / h)
                << "r " << r << " n " << n.transpose() << " side " << side << " offset " << offset
                << "\ntangent\n"
                << t << "\nfd\n"
                << fd;
            EXPECT_EQ(t, t.transpose()); // symmetric: the gradient of (3.7)
          }
}

TEST(NodeToRigid, ActiveStatePushesAlongNormal) {
  for (const auto& n : kNormals) {
    const double g = 0.25, lambda = 3.0, r = 10.0;
    // On the obstacle: u_n = g, plus any tangential slip.
    const Eigen::Vector2d u = -g * n + 0.4 * Eigen::Vector2d(-n.y(), n.x());
    NodeToRigidVector x;
    x << u, lambda;
    const NodeToRigidVector f = alart_curnier_residual(x, n, g, r);
    // The residual row adds to A(u) - f: the body receives -f_u = lambda n.
    EXPECT_NEAR((-f.head<2>() - lambda * n).norm(), 0, 1e-14);
    EXPECT_NEAR(f(2), 0, 1e-15); // Signorini state: the complementarity row vanishes
    // Off the obstacle with lambda = 0: no force, no residual.
    x << -(g - 0.1) * n, 0.0;
    EXPECT_NEAR(alart_curnier_residual(x, n, g, r).norm(), 0, 1e-15);
  }
}

TEST(NodeToRigid, PenaltyTangentMatchesFiniteDifferences) {
  for (double r : {1.0, 1e3, 1e6})
    for (const auto& n : kNormals)
      for (double side : {-1.0, 1.0})
        for (double offset : {1e-6, 1e-3, 1.0}) {
          const double g = 0.1;
          const Eigen::Vector2d u = -(g + side * offset) * n + 0.3 * Eigen::Vector2d(-n.y(), n.x());
          const double h = offset / 8;
          Eigen::Matrix2d fd;
          for (int k = 0; k < 2; ++k) {
            Eigen::Vector2d e = Eigen::Vector2d::Zero();
            e(k) = h;
            fd.col(k) =
                (penalty_residual(u + e, n, g, r) - penalty_residual(u - e, n, g, r)) / (2 * h);
          }
          EXPECT_LE((penalty_tangent(u, n, g, r) - fd).cwiseAbs().maxCoeff(),
                    1e-7 * r + 1e-14 * r / h);
          // Penetration by `offset` gives the force r * offset along +n on the body.
          const Eigen::Vector2d expected =
              side > 0 ? Eigen::Vector2d(r * offset * n) : Eigen::Vector2d::Zero();
          EXPECT_NEAR((-penalty_residual(u, n, g, r) - expected).norm(), 0, 1e-9 * (1 + r));
        }
}

} // namespace
} // namespace sig
