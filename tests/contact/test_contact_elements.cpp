// Contact elements on hand-made square meshes: tributary weights, gaps and normals against closed
// forms, boundary order, B_N rows, and geometric errors.
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "square_mesh.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace sig {
namespace {

using test::scrambled;
using test::square_mesh;
using test::square_node;

const HalfPlane kFoundation({0, 0}, {0, 1}); // x2 <= 0

TEST(ContactElements, SquareRestingOnTheFoundation) {
  const int n = 4;
  const double side = 2.0, h = side / n;
  const Mesh mesh = square_mesh(n, side, 0.0, scrambled(n));
  const ContactElements e = build_contact_elements(mesh, 3, kFoundation);
  ASSERT_EQ(e.size(), n + 1);
  EXPECT_EQ(e.num_nodes, mesh.num_nodes());
  EXPECT_EQ(e.ref, 3);
  EXPECT_NEAR(e.weight.sum(), side, 1e-14); // bottom length x thickness 1
  for (int i = 0; i < e.size(); ++i) {
    const Eigen::Vector2d& x = mesh.nodes[e.node[i]];
    EXPECT_EQ(x.y(), 0.0);
    // Boundary order: counter-clockwise along the bottom is left to right.
    EXPECT_NEAR(x.x(), i * h, 1e-14) << "element " << i;
    EXPECT_EQ(e.lagrange_node[i], mesh.num_nodes() + i);
    EXPECT_EQ(e.gap(i), 0.0);
    EXPECT_EQ(e.normal[i], Eigen::Vector2d(0, 1));
    EXPECT_EQ(e.tangent[i], Eigen::Vector2d(1, 0)); // +x1 on the foundation: S+ of the thesis
    EXPECT_EQ(e.law[i], ContactLaw{});
    EXPECT_EQ(e.bound(i), 0.0);
    // End nodes carry half an edge, inner nodes two halves.
    const bool end = i == 0 || i == n;
    EXPECT_NEAR(e.weight(i), end ? h / 2 : h, 1e-14);
  }
  EXPECT_EQ(e.obstacle.kind, "plane");
  EXPECT_EQ(e.obstacle.normal, Eigen::Vector2d(0, 1));
}

TEST(ContactElements, ThicknessScalesWeights) {
  const Mesh mesh = square_mesh(3, 1.5);
  const ContactElements e = build_contact_elements(mesh, 3, kFoundation, {}, 0.2);
  EXPECT_NEAR(e.weight.sum(), 1.5 * 0.2, 1e-14);
  EXPECT_EQ(e.thickness, 0.2);
}

TEST(ContactElements, LiftedSquareHasTheLiftAsGap) {
  for (double lift : {1e-6, 0.3, 12.0}) {
    const Mesh mesh = square_mesh(5, 1.0, lift);
    const ContactElements e = build_contact_elements(mesh, 3, kFoundation);
    for (int i = 0; i < e.size(); ++i)
      EXPECT_NEAR(e.gap(i), lift, 1e-15 * (1 + lift));
    // A wall depth g leaves the gap and moves the unilateral bound by g.
    ContactLaw deeper;
    deeper.depth = 0.05;
    const ContactElements f = build_contact_elements(mesh, 3, kFoundation, deeper);
    for (int i = 0; i < f.size(); ++i) {
      EXPECT_NEAR(f.gap(i), lift, 1e-15 * (1 + lift));
      EXPECT_NEAR(f.bound(i), lift + 0.05, 1e-15 * (1 + lift));
    }
    // Pure compliance has no wall.
    ContactLaw compliance;
    compliance.normal = NormalLaw::compliance;
    compliance.cn = 10;
    EXPECT_EQ(build_contact_elements(mesh, 3, kFoundation, compliance).bound(0), INFINITY);
  }
}

TEST(ContactElements, TiltedPlaneGapsAndNormalOperator) {
  // Plane through (0, -1) with normal (1, 2)/sqrt 5: the bottom node (x, 0) has gap (x + 2)/sqrt 5.
  const HalfPlane plane({0, -1}, {1, 2});
  const Eigen::Vector2d n = Eigen::Vector2d(1, 2) / std::sqrt(5.0);
  const int count = 4;
  const Mesh mesh = square_mesh(count, 1.0, 0.0, scrambled(count));
  const ContactElements e = build_contact_elements(mesh, 3, plane);
  const int ndof = 2 * mesh.num_nodes();
  const Eigen::SparseMatrix<double> b_n = normal_operator(e, ndof);
  ASSERT_EQ(b_n.rows(), e.size());
  ASSERT_EQ(b_n.cols(), ndof);
  EXPECT_EQ(b_n.nonZeros(), 2 * e.size());
  for (int i = 0; i < e.size(); ++i) {
    const int k = e.node[i];
    EXPECT_NEAR(e.gap(i), (mesh.nodes[k].x() + 2) / std::sqrt(5.0), 1e-14);
    EXPECT_NEAR((e.normal[i] - n).norm(), 0, 1e-15);
    // Row i is -n^T on the dofs (2k, 2k+1) of node k.
    EXPECT_DOUBLE_EQ(b_n.coeff(i, 2 * k), -n.x());
    EXPECT_DOUBLE_EQ(b_n.coeff(i, 2 * k + 1), -n.y());
  }
  // (B_N u)_i = -n . u_k: a motion towards the plane is positive, along it zero.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(ndof);
  for (int k = 0; k < mesh.num_nodes(); ++k)
    u.segment<2>(2 * k) = -0.5 * n + 3.0 * Eigen::Vector2d(-n.y(), n.x());
  const Eigen::VectorXd un = b_n * u;
  for (int i = 0; i < e.size(); ++i)
    EXPECT_NEAR(un(i), 0.5, 1e-14);
  // Too few dofs for the contact nodes is an error.
  EXPECT_THROW(normal_operator(e, ndof / 2), Error);
}

TEST(ContactElements, SquareAboveARigidDisc) {
  // Disc centre (0.5, -2), radius 2: it touches the bottom at (0.5, 0).
  const Disc disc({0.5, -2}, 2);
  const Mesh mesh = square_mesh(4);
  const ContactElements e = build_contact_elements(mesh, 3, disc);
  EXPECT_EQ(e.obstacle.kind, "disc");
  EXPECT_EQ(e.obstacle.radius, 2);
  for (int i = 0; i < e.size(); ++i) {
    const Eigen::Vector2d x = mesh.nodes[e.node[i]];
    const Eigen::Vector2d radial(x.x() - 0.5, 2.0);
    EXPECT_NEAR(e.gap(i), radial.norm() - 2, 1e-14);
    EXPECT_NEAR((e.normal[i] - radial.normalized()).norm(), 0, 1e-15);
  }
  EXPECT_EQ(e.gap(2), 0.0); // the node (0.5, 0) touches
}

TEST(ContactElements, OrderFollowsTheBoundaryAroundCorners) {
  // Reference 2 = right side (upwards) then top (leftwards): one chain through the corner (1, 1).
  const int n = 3;
  const Mesh mesh = square_mesh(n, 1.0, 0.0, scrambled(n));
  const auto perm = scrambled(n);
  const ContactElements e = build_contact_elements(mesh, 2, HalfPlane({0, 5}, {0, -1}));
  std::vector<int> expected;
  for (int j = 0; j <= n; ++j)
    expected.push_back(perm[square_node(n, n, j)]);
  for (int i = n - 1; i >= 0; --i)
    expected.push_back(perm[square_node(n, i, n)]);
  EXPECT_EQ(e.node, expected);
  EXPECT_NEAR(e.weight.sum(), 2.0, 1e-14);
  // The corner node carries half of one edge from each side.
  EXPECT_NEAR(e.weight(n), 1.0 / n, 1e-14);
  // Gaps to the ceiling x2 = 5 (obstacle above, normal pointing down).
  for (int i = 0; i < e.size(); ++i)
    EXPECT_NEAR(e.gap(i), 5 - mesh.nodes[e.node[i]].y(), 1e-14);
}

TEST(ContactElements, ClosedChainStartsAtItsSmallestNode) {
  // Every boundary edge with one reference: a closed chain, walked counter-clockwise.
  Mesh mesh = square_mesh(2);
  for (Facet& edge : mesh.facets)
    edge.ref = 5;
  const ContactElements e = build_contact_elements(mesh, 5, HalfPlane({0, -1}, {0, 1}));
  const std::vector<int> expected = {0, 1, 2, 5, 8, 7, 6, 3};
  EXPECT_EQ(e.node, expected);
  EXPECT_NEAR(e.weight.sum(), 4.0, 1e-14);
}

TEST(ContactElements, BranchingEdgesFallBackToNodeOrder) {
  // Three edges with ref 3 meeting at node 4 (centre of a 2x2 square): not a chain.
  Mesh mesh = square_mesh(2);
  mesh.facets = {{{4, 1}, 3}, {{4, 3}, 3}, {{4, 5}, 3}};
  const ContactElements e = build_contact_elements(mesh, 3, kFoundation);
  EXPECT_EQ(e.node, (std::vector<int>{1, 3, 4, 5}));
  EXPECT_NEAR(e.weight(2), 3 * 0.25, 1e-14);
}

TEST(ContactElements, DuplicateEdgesCountOnce) {
  Mesh mesh = square_mesh(2);
  mesh.facets.push_back({{1, 0}, 3}); // the first bottom edge again, reversed
  const ContactElements e = build_contact_elements(mesh, 3, kFoundation);
  EXPECT_EQ(e.size(), 3);
  EXPECT_NEAR(e.weight.sum(), 1.0, 1e-14);
}

TEST(ContactElements, GeometricErrors) {
  const Mesh mesh = square_mesh(2);
  // A node inside the obstacle: the plane x2 = 0.25 cuts the square.
  EXPECT_THROW(build_contact_elements(mesh, 3, HalfPlane({0, 0.25}, {0, 1})), Error);
  // No edge with the reference.
  EXPECT_THROW(build_contact_elements(mesh, 9, kFoundation), Error);
  ContactLaw negative;
  negative.depth = -0.1;
  EXPECT_THROW(build_contact_elements(mesh, 3, kFoundation, negative), Error);
  EXPECT_THROW(build_contact_elements(mesh, 3, kFoundation, {}, 0.0), Error);
  // Roundoff below the plane is a touching node, not a penetration.
  const ContactElements e = build_contact_elements(mesh, 3, HalfPlane({0, 1e-14}, {0, 1}));
  for (int i = 0; i < e.size(); ++i)
    EXPECT_EQ(e.gap(i), 0.0);
}

TEST(ContactElements, GapAtCurrentPosition) {
  const Disc disc({0, 0}, 1);
  EXPECT_DOUBLE_EQ(gap_at(disc, {0, 3}), 2);
  EXPECT_DOUBLE_EQ(gap_at(kFoundation, Eigen::Vector2d(0.2, 0.5) + Eigen::Vector2d(0, -0.7)), -0.2);
}

} // namespace
} // namespace sig
