// The 3D generators through gmsh (meshes/box.geo, meshes/half_ball.geo): tetrahedra filling
// the body, the references the scenes use.
#include "mesh/generators.hpp"
#include "mesh/mesh.hpp"
#include "mesh_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sig {
namespace {

TEST(Generators3d, Box) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "no gmsh";
  const Mesh mesh = box(2, 1, 0.5, 0.25);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_NEAR(testing::measure_of(mesh), 1.0, 1e-12);
  EXPECT_EQ(mesh.references(), (std::vector<int>{1, 2, 3}));
  for (int i : mesh.nodes_with_ref(1))
    EXPECT_EQ(mesh.nodes[i].z(), 0);
  for (int i : mesh.nodes_with_ref(2))
    EXPECT_EQ(mesh.nodes[i].z(), 0.5);
}

TEST(Generators3d, HalfBall) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "no gmsh";
  const double R = 2;
  const Mesh mesh = half_ball(R, 0.5);
  EXPECT_EQ(mesh.dim, 3);
  // A polyhedron inscribed in the half ball: a little less than its volume.
  const double exact = 2 * std::numbers::pi * R * R * R / 3;
  EXPECT_LT(testing::measure_of(mesh), exact);
  EXPECT_GT(testing::measure_of(mesh), 0.9 * exact);
  const std::vector<int> centre = mesh.nodes_with_ref(1);
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_NEAR((mesh.nodes[centre[0]] - Point(0, 0, R)).norm(), 0, 1e-12);
  for (int i : mesh.nodes_with_ref(3))
    EXPECT_NEAR((mesh.nodes[i] - Point(0, 0, R)).norm(), R, 1e-6 * R);
  for (int i : mesh.nodes_with_ref(2))
    EXPECT_NEAR(mesh.nodes[i].z(), R, 1e-12);
}

// Graded towards the pole (size h + grading x distance, capped): the pole is a node, the mesh is
// fine there and coarse away from it, so that it has fewer nodes than the uniform mesh of size h;
// the references are the uniform mesh's.
TEST(Generators3d, HalfBallGraded) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "no gmsh";
  const double R = 2, h = 0.2;
  const Mesh uniform = half_ball(R, h);
  const Mesh graded = half_ball(R, h, 0.3);
  EXPECT_LT(graded.nodes.size(), uniform.nodes.size() / 2);
  EXPECT_EQ(graded.references(), uniform.references());
  const auto pole =
      std::min_element(graded.nodes.begin(), graded.nodes.end(),
                       [](const Point& a, const Point& b) { return a.norm() < b.norm(); });
  EXPECT_LT(pole->norm(), 1e-12 * R);
  // The nodes nearest the pole are about h away; the top's nodes, capped at R / 4, farther.
  double nearest = 1e300;
  for (const Point& x : graded.nodes)
    if (x.norm() > 1e-12 * R) nearest = std::min(nearest, x.norm());
  EXPECT_LT(nearest, 1.5 * h);
  EXPECT_GT(nearest, 0.3 * h);
  const double exact = 2 * std::numbers::pi * R * R * R / 3;
  EXPECT_GT(testing::measure_of(graded), 0.9 * exact);
  EXPECT_LT(testing::measure_of(graded), exact);
}

TEST(Generators3d, Ball) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "no gmsh";
  const Point centre(1, -2, 3);
  const double R = 0.5;
  const Mesh mesh = ball(centre, R, 0.2);
  EXPECT_EQ(mesh.dim, 3);
  const double exact = 4 * std::numbers::pi * R * R * R / 3;
  EXPECT_LT(testing::measure_of(mesh), exact);
  EXPECT_GT(testing::measure_of(mesh), 0.9 * exact);
  EXPECT_EQ(mesh.references(), std::vector<int>{3});
  for (int i : mesh.nodes_with_ref(3))
    EXPECT_NEAR((mesh.nodes[i] - centre).norm(), R, 1e-6 * R);
}

TEST(Generators3d, Cylinder) {
  if (!testing::have_gmsh()) GTEST_SKIP() << "no gmsh";
  const double R = 1, L = 0.5;
  const Mesh mesh = cylinder(R, L, 0.3);
  EXPECT_EQ(mesh.dim, 3);
  const double exact = std::numbers::pi * R * R * L;
  EXPECT_LT(testing::measure_of(mesh), exact);
  EXPECT_GT(testing::measure_of(mesh), 0.9 * exact);
  EXPECT_EQ(mesh.references(), (std::vector<int>{2, 3}));
  for (int i : mesh.nodes_with_ref(2))
    EXPECT_TRUE(std::abs(mesh.nodes[i].y()) < 1e-12 || std::abs(mesh.nodes[i].y() - L) < 1e-12);
  // The tread: at distance R from the axis x1 = 0, x3 = R; its lowest point on x3 = 0.
  double lowest = R;
  for (int i : mesh.nodes_with_ref(3)) {
    EXPECT_NEAR(std::hypot(mesh.nodes[i].x(), mesh.nodes[i].z() - R), R, 1e-6 * R);
    lowest = std::min(lowest, mesh.nodes[i].z());
  }
  EXPECT_NEAR(lowest, 0, 1e-9);
}

} // namespace
} // namespace sig
