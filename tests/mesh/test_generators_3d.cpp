// The 3D generators through gmsh (meshes/box.geo, meshes/half_ball.geo): tetrahedra filling
// the body, the references the scenes use.
#include "mesh/generators.hpp"
#include "mesh/mesh.hpp"
#include "mesh_testing.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace sig
