// The gmsh reader in 3D: tetrahedra, physical volumes (sub-domains) and physical surfaces
// (references on boundary triangles), formats 2.2 and 4.1, ASCII and binary; a surface with no
// volume and a surface beside the volume refused.
#include "core/error.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"
#include "mesh_testing.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

namespace sig {
namespace {

// gmsh 4.8 meshed the unit cube (OpenCASCADE Box, Mesh.CharacteristicLengthMin = Max = 0.5,
// Physical Volume 1, Physical Surface 1 = the base z = 0, 2 = the top z = 1, 3 = the four
// sides) and saved it with `gmsh -3 [-bin] -format msh22|msh41`.
std::filesystem::path corpus(const std::string& name) {
  return std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" / name;
}

using testing::error_of;

/// `text` with its first `from` replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

TEST(GmshReader3d, CubeOfTetrahedra) {
  const Mesh mesh = read_gmsh(corpus("box_v22_ascii.msh"));
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.num_cells(), 101);
  EXPECT_EQ(mesh.facets.size(), 84u);
  EXPECT_EQ(mesh.subdomains(), std::vector<int>{1});
  EXPECT_EQ(mesh.references(), (std::vector<int>{1, 2, 3}));
  EXPECT_NEAR(testing::measure_of(mesh), 1.0, 1e-14);
  for (const Point& x : mesh.nodes)
    EXPECT_EQ(x.size(), 3);
  // Every referenced face lies on its plane of the cube and turns outward.
  double base_area = 0;
  for (const Facet& f : mesh.facets) {
    const Eigen::Vector3d a = mesh.nodes[f.node[0]], b = mesh.nodes[f.node[1]],
                          c = mesh.nodes[f.node[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    const Eigen::Vector3d centre = (a + b + c) / 3;
    EXPECT_GT(normal.dot(centre - Eigen::Vector3d::Constant(0.5)), 0)
        << "face " << f.node[0] << " " << f.node[1];
    if (f.ref == 1) {
      EXPECT_EQ(a.z(), 0);
      EXPECT_LT(normal.z(), 0);
      base_area += normal.norm() / 2;
    }
    if (f.ref == 2) {
      EXPECT_EQ(c.z(), 1);
    }
  }
  EXPECT_NEAR(base_area, 1.0, 1e-14);
}

TEST(GmshReader3d, BinaryAndFormat41ReadAsTheAsciiTwin) {
  const Mesh a = read_gmsh(corpus("box_v22_ascii.msh"));
  for (const char* name : {"box_v22_binary.msh", "box_v41_ascii.msh", "box_v41_binary.msh"}) {
    const Mesh b = read_gmsh(corpus(name));
    ASSERT_EQ(a.num_nodes(), b.num_nodes()) << name;
    // gmsh writes 16 digits in ASCII, all 17 of a double in binary.
    for (int i = 0; i < a.num_nodes(); ++i)
      EXPECT_LE((a.nodes[i] - b.nodes[i]).norm(), 1e-15) << name << " node " << i;
    EXPECT_EQ(a.cells, b.cells) << name;
    EXPECT_EQ(a.subdomain, b.subdomain) << name;
    ASSERT_EQ(a.facets.size(), b.facets.size()) << name;
    for (std::size_t e = 0; e < a.facets.size(); ++e) {
      EXPECT_EQ(a.facets[e].node, b.facets[e].node) << name;
      EXPECT_EQ(a.facets[e].ref, b.facets[e].ref) << name;
    }
  }
}

// One tetrahedron, a face of it and a triangle off it: text written here.
const std::string one_tetrahedron = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
5
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
5 3 3 3
$EndNodes
$Elements
2
1 2 2 7 1 1 2 3
2 4 2 1 1 1 2 3 4
$EndElements
)";

TEST(GmshReader3d, OneTetrahedronItsFaceOutwardAndTheUnusedNodeDropped) {
  const Mesh mesh = parse_gmsh("one.msh", one_tetrahedron);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.num_nodes(), 4);
  ASSERT_EQ(mesh.facets.size(), 1u);
  EXPECT_EQ(mesh.facets[0].ref, 7);
  // The base z = 0, listed counter-clockwise from above in the file, is turned to face down.
  const Eigen::Vector3d a = mesh.nodes[mesh.facets[0].node[0]],
                        b = mesh.nodes[mesh.facets[0].node[1]],
                        c = mesh.nodes[mesh.facets[0].node[2]];
  EXPECT_LT((b - a).cross(c - a).z(), 0);
}

TEST(GmshReader3d, ALeftHandedTetrahedronIsReoriented) {
  const std::string swapped = replaced(one_tetrahedron, "2 4 2 1 1 1 2 3 4", "2 4 2 1 1 1 3 2 4");
  const Mesh mesh = parse_gmsh("left.msh", swapped);
  EXPECT_GT(signed_cell_determinant(mesh, 0), 0);
}

TEST(GmshReader3d, AFlatTetrahedronIsRefusedWithItsLine) {
  const std::string flat = replaced(one_tetrahedron, "4 0 0 1\n", "4 1 1 0\n");
  const std::string message = error_of([&] { parse_gmsh("flat.msh", flat); });
  EXPECT_NE(message.find("flat.msh:15"), std::string::npos) << message;
  EXPECT_NE(message.find("tetrahedron 1 (1-based) is degenerate"), std::string::npos) << message;
}

TEST(GmshReader3d, ASurfaceWithNoVolumeIsRefused) {
  const std::string surface = replaced(
      replaced(replaced(one_tetrahedron, "2\n1 2 2 7", "1\n1 2 2 7"), "2 4 2 1 1 1 2 3 4\n", ""),
      "1 0 0 0\n", "1 0 0 2\n");
  const std::string message = error_of([&] { parse_gmsh("surface.msh", surface); });
  EXPECT_NE(message.find("surface.msh:6"), std::string::npos) << message;
  EXPECT_NE(message.find("no tetrahedra"), std::string::npos) << message;
}

TEST(GmshReader3d, ASurfaceBesideTheVolumeIsRefused) {
  const std::string mixed = replaced(replaced(one_tetrahedron, "2\n1 2 2 7", "3\n1 2 2 7"),
                                     "$EndElements", "3 2 2 8 2 2 3 5\n$EndElements");
  const std::string message = error_of([&] { parse_gmsh("mixed.msh", mixed); });
  EXPECT_NE(message.find("mixed.msh:16"), std::string::npos) << message;
  EXPECT_NE(message.find("mixed dimensions"), std::string::npos) << message;
}

TEST(CheckMesh3d, AnInvertedTetrahedronIsNamed) {
  Mesh mesh = parse_gmsh("one.msh", one_tetrahedron);
  std::swap(mesh.cells[0][1], mesh.cells[0][2]);
  const std::string message = error_of([&] { check_mesh(mesh, "m"); });
  EXPECT_NE(message.find("tetrahedron 1 (1-based) is inverted or degenerate"), std::string::npos)
      << message;
}

TEST(CheckMesh3d, AFlatTetrahedronIsNamed) {
  Mesh mesh = parse_gmsh("one.msh", one_tetrahedron);
  mesh.nodes[mesh.cells[0][3]] = Point(0.2, 0.2, 1e-9);
  const std::string message = error_of([&] { check_mesh(mesh, "m"); });
  EXPECT_NE(message.find("tetrahedron 1 (1-based) is flat"), std::string::npos) << message;
}

} // namespace
} // namespace sig
