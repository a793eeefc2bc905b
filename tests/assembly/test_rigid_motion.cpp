// The parts of a body and the rigid motions its held dofs leave free (assembly/rigid_motion.hpp),
// on unit squares of two triangles put together by hand: a free square, a pinned one, one on
// rollers, a second square held by nothing, one hinged at a corner, and a three-hinged arch,
// which its two pins and its hinge hold (no part is free although each alone would turn).
#include "assembly/rigid_motion.hpp"
#include "core/error.hpp"

#include <gtest/gtest.h>

#include <map>

namespace sig {
namespace {

/// Unit squares with these lower-left corners, each of two triangles and its own sub-domain
/// (1, 2, ...); squares that touch share their nodes.
Mesh squares(const std::vector<Eigen::Vector2d>& corners) {
  Mesh mesh;
  std::map<std::pair<double, double>, int> index;
  const auto node = [&](const Eigen::Vector2d& x) {
    const auto [it, fresh] = index.try_emplace({x.x(), x.y()}, mesh.num_nodes());
    if (fresh) mesh.nodes.push_back(x);
    return it->second;
  };
  for (std::size_t s = 0; s < corners.size(); ++s) {
    const Eigen::Vector2d c = corners[s];
    const int a = node(c), b = node(c + Eigen::Vector2d(1, 0)), d = node(c + Eigen::Vector2d(1, 1)),
              e = node(c + Eigen::Vector2d(0, 1));
    mesh.cells.push_back({a, b, d});
    mesh.cells.push_back({a, d, e});
    mesh.subdomain.insert(mesh.subdomain.end(), 2, static_cast<int>(s) + 1);
  }
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  return mesh;
}

/// Both dofs of the node at x.
std::vector<int> pin(const Mesh& mesh, const Eigen::Vector2d& x) {
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.nodes[n] == x) return {2 * n, 2 * n + 1};
  ADD_FAILURE() << "no node at " << x.transpose();
  return {};
}

std::vector<int> operator+(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// The free parts that the Dirichlet dofs `dofs` leave.
std::vector<FreePart> free_of(const Mesh& mesh, const std::vector<int>& dofs) {
  return free_parts(mesh, holds_of(dofs).holds);
}

TEST(FreeParts, OneSquareFreePinnedOnRollersAndClamped) {
  const Mesh mesh = squares({{0, 0}});
  std::vector<FreePart> parts = free_of(mesh, {});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_TRUE(parts[0].whole_body);
  EXPECT_EQ(parts[0].motions, "the translation along x1, the translation along x2 and the "
                              "rotation about (0.5, 0.5)");
  EXPECT_EQ(describe(parts[0]), "the body is free to move: nothing holds " + parts[0].motions);
  parts = free_of(mesh, pin(mesh, {1, 1}));
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].motions, "the rotation about (1, 1)");
  // Rollers: u2 = 0 along the bottom leaves the translation along x1.
  parts = free_of(mesh, {1, 3});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].motions, "the translation along x1");
  EXPECT_TRUE(free_of(mesh, pin(mesh, {0, 0}) + pin(mesh, {0, 1})).empty());
}

TEST(FreeParts, ASecondBodyHeldByNothingIsNamed) {
  const Mesh mesh = squares({{0, 0}, {2, 0}});
  const std::vector<FreePart> parts = free_of(mesh, pin(mesh, {0, 0}) + pin(mesh, {0, 1}));
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_FALSE(parts[0].whole_body);
  EXPECT_EQ(parts[0].subdomains, std::vector<int>{2});
  EXPECT_EQ(parts[0].nodes, (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(describe(parts[0]),
            "the part of sub-domain 2 (4 nodes: 5, 6, 7, 8, around (2.5, 0.5); references on it: "
            "none) is free to move: nothing holds the translation along x1, the translation along "
            "x2 and the rotation about (2.5, 0.5)");
  try {
    verify_rigid_motions_held(mesh, holds_of(pin(mesh, {0, 0}) + pin(mesh, {0, 1})), "b.dat");
    ADD_FAILURE() << "a free part accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.dat: the part of sub-domain 2"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(4 imposed dofs, no CONTACT card)"), std::string::npos);
  }
}

TEST(FreeParts, AHingeTurnsAndAThreeHingedArchIsHeld) {
  // The second square meets the first, which is clamped, at the corner (1, 1) only.
  const Mesh hinged = squares({{0, 0}, {1, 1}});
  const std::vector<FreePart> parts = free_of(hinged, pin(hinged, {0, 0}) + pin(hinged, {0, 1}));
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].motions,
            "the rotation about (1, 1), the one node where it meets the rest of the body");
  // Pinned at (0, 0) and (2, 1) and hinged at (1, 1): each square would turn about its pin, the
  // hinge forbids it (the three points are not aligned).
  EXPECT_TRUE(free_of(hinged, pin(hinged, {0, 0}) + pin(hinged, {2, 1})).empty());
  // Pinned at (0, 0) and (2, 2), in line with the hinge: the arch folds there.
  EXPECT_EQ(free_of(hinged, pin(hinged, {0, 0}) + pin(hinged, {2, 2})).size(), 2u);
}

// A frictionless contact holds its nodes along the obstacle's normal only: a body on a flat wall
// slides along it; a disc's normals, not parallel, hold it (but for its turning about the centre).
TEST(FreeParts, ContactNodesHoldAlongTheirNormalsOrWhollyWithFriction) {
  const Mesh mesh = squares({{0, 0}});
  const std::vector<Eigen::Vector2d> up(2, Eigen::Vector2d(0, 1));
  const Holds on_wall = holds_of({}, {0, 1}, up);
  EXPECT_EQ(on_wall.holders,
            "0 imposed dofs and 2 contact nodes, frictionless: along their normals");
  std::vector<FreePart> parts = free_parts(mesh, on_wall.holds);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].motions, "the translation along x1");
  EXPECT_TRUE(free_parts(mesh, holds_of({}, {0, 1}, up, true).holds).empty());
  // Normals towards the centre (2, 2) of a disc: the square turns about it.
  const std::vector<Eigen::Vector2d> radial = {Eigen::Vector2d(2, 2).normalized(),
                                               Eigen::Vector2d(1, 2).normalized()};
  parts = free_parts(mesh, holds_of({}, {0, 1}, radial).holds);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].motions, "the rotation about (2, 2)");
}

TEST(FreeParts, AThinStripClampedAtOneEndIsHeld) {
  Mesh strip = squares({{0, 0}});
  for (Point& x : strip.nodes)
    x.y() *= 1e-5; // 1 long, 1e-5 thick
  EXPECT_TRUE(free_of(strip, pin(strip, {0, 0}) + pin(strip, {0, 1e-5})).empty());
}

} // namespace
} // namespace sig
