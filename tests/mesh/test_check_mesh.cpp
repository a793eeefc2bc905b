// check_mesh and the Mesh queries on a hand-made two-triangle square.
#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"
#include "two_triangles.hpp"

#include <gtest/gtest.h>

namespace sig {
namespace {

// With three boundary edges and a reference on one vertex.
Mesh unit_square() {
  Mesh mesh = test::two_triangle_square();
  mesh.facets = {{{0, 1}, 3}, {{1, 2}, 4}, {{3, 0}, 1}};
  mesh.vertex_ref = {0, 0, 7, 0};
  return mesh;
}

std::string message(const Mesh& mesh) {
  try {
    check_mesh(mesh, "unit.msh");
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CheckMesh, AcceptsAValidMesh) {
  EXPECT_EQ(message(unit_square()), "accepted");
  EXPECT_DOUBLE_EQ(signed_double_area(unit_square(), 1), 1.0);
}

TEST(CheckMesh, RejectsAnInvertedTriangle) {
  Mesh mesh = unit_square();
  std::swap(mesh.cells[1][1], mesh.cells[1][2]);
  EXPECT_EQ(message(mesh),
            "unit.msh: triangle 2 (1-based) is inverted or degenerate (signed area -0.5)");
  mesh.cells[1] = {0, 2, 2};
  EXPECT_NE(message(mesh).find("triangle 2 (1-based) is inverted or degenerate"),
            std::string::npos);
}

TEST(CheckMesh, RejectsAnUnusedNode) {
  Mesh mesh = unit_square();
  mesh.nodes.emplace_back(5, 5);
  mesh.vertex_ref.push_back(0);
  EXPECT_EQ(message(mesh), "unit.msh: node 5 (1-based) is used by no triangle");
  drop_unused_nodes(mesh);
  EXPECT_EQ(message(mesh), "accepted");
}

TEST(CheckMesh, RejectsBadIndicesSubdomainsAndEdges) {
  Mesh mesh = unit_square();
  mesh.cells[0][2] = 4;
  EXPECT_NE(message(mesh).find("triangle 1 (1-based) uses node 5, out of range 1..4"),
            std::string::npos);
  mesh = unit_square();
  mesh.subdomain[1] = 0;
  EXPECT_NE(message(mesh).find("sub-domain 0"), std::string::npos);
  mesh = unit_square();
  mesh.facets.push_back({{0, 2}, 2}); // the diagonal: an interface, a side of both triangles
  EXPECT_EQ(message(mesh), "accepted");
  mesh.facets.push_back({{0, 0}, 2});
  EXPECT_NE(message(mesh).find("edge 5 (1-based)"), std::string::npos);
  mesh = unit_square();
  mesh.vertex_ref.pop_back();
  EXPECT_NE(message(mesh).find("vertex references"), std::string::npos);
}

TEST(MeshQueries, ReferencesAndNodes) {
  const Mesh mesh = unit_square();
  EXPECT_EQ(mesh.references(), (std::vector<int>{1, 3, 4, 7}));
  EXPECT_EQ(mesh.nodes_with_ref(4), (std::vector<int>{1, 2}));
  EXPECT_EQ(mesh.nodes_with_ref(7), (std::vector<int>{2}));
  EXPECT_EQ(mesh.facets_with_ref(1).size(), 1u);
  EXPECT_EQ(mesh.subdomains(), std::vector<int>{1});
}

TEST(Topology, OrientationHelpers) {
  Mesh mesh = unit_square();
  std::swap(mesh.cells[0][1], mesh.cells[0][2]);
  mesh.facets[0] = {{1, 0}, 3};       // wrong way round
  mesh.facets.push_back({{0, 1}, 3}); // repeated
  orient_cells(mesh);
  EXPECT_GT(signed_double_area(mesh, 0), 0);
  EXPECT_EQ(orient_facets(mesh), -1);
  ASSERT_EQ(mesh.facets.size(), 3u);
  EXPECT_EQ(mesh.facets[0].node[0], 0);
  EXPECT_EQ(mesh.facets[0].node[1], 1);
  mesh.facets.push_back({{0, 5}, 2});
  EXPECT_EQ(orient_facets(mesh), 3);
}

} // namespace
} // namespace sig
