// gmsh (2.2 and 4.1) and FreeFem .msh readers on small files written here.
#include "core/error.hpp"
#include "mesh/freefem.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh_card.hpp"
#include "mesh_testing.hpp"

#include <functional>

namespace sig {
namespace {

using testing::ScratchFolder;
using testing::spit;

// The unit square cut into 4 triangles around its centre; node 60 is a geometry point that no
// element uses, triangle 5 is clockwise, the bottom line runs backwards, the top line is listed
// twice and one line has no physical tag.
const char* square_v22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 3 "contact zone"
2 7 "body"
$EndPhysicalNames
$Nodes
6
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
50 0.5 0.5 0
60 5 5 0
$EndNodes
$Elements
9
1 15 2 1 1 10
2 1 2 3 1 20 10
3 1 2 0 2 20 30
4 2 2 7 1 10 20 50
5 2 2 7 1 20 50 30
6 2 2 7 1 30 40 50
7 2 2 7 1 40 10 50
8 1 2 4 3 30 40
9 1 2 4 3 40 30
$EndElements
)";

// The same mesh in format 4.1: physical tags on entities, one parametric node block.
const char* square_v41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
2 2 1 0
1 0 0 0 1 1
2 5 5 0 0
1 0 0 0 1 0 0 1 3 2 1 -2
2 0 1 0 1 1 0 1 4 0
1 0 0 0 1 1 0 1 7 2 1 2
$EndEntities
$Nodes
4 6 10 60
0 1 0 1
10
0 0 0
0 2 0 1
60
5 5 0
1 1 1 1
20
1 0 0 0.5
2 1 0 3
30
40
50
1 1 0
0 1 0
0.5 0.5 0
$EndNodes
$Elements
4 8 1 8
0 1 15 1
1 10
1 1 1 1
2 20 10
1 2 1 1
3 30 40
2 1 2 4
4 10 20 50
5 20 50 30
6 30 40 50
7 40 10 50
$EndElements
)";

void expect_square(const Mesh& mesh) {
  ASSERT_EQ(mesh.num_nodes(), 5); // node 60 dropped, the others in file order
  EXPECT_EQ(mesh.nodes[1], Eigen::Vector2d(1, 0));
  EXPECT_EQ(mesh.nodes[4], Eigen::Vector2d(0.5, 0.5));
  ASSERT_EQ(mesh.num_cells(), 4);
  for (int t = 0; t < 4; ++t)
    EXPECT_DOUBLE_EQ(signed_double_area(mesh, t), 0.5);
  EXPECT_EQ(mesh.subdomain, std::vector<int>(4, 7));
  ASSERT_EQ(mesh.facets.size(), 2u);
  EXPECT_EQ(mesh.facets[0].node[0], 0); // turned round: domain on the left
  EXPECT_EQ(mesh.facets[0].node[1], 1);
  EXPECT_EQ(mesh.facets[0].ref, 3);
  EXPECT_EQ(mesh.facets[1].node[0], 2);
  EXPECT_EQ(mesh.facets[1].node[1], 3);
  EXPECT_EQ(mesh.facets[1].ref, 4);
  EXPECT_EQ(mesh.vertex_ref, (std::vector<int>{1, 0, 0, 0, 0}));
  EXPECT_EQ(mesh.nodes_with_ref(3), (std::vector<int>{0, 1}));
  EXPECT_EQ(mesh.references(), (std::vector<int>{1, 3, 4}));
}

TEST(GmshReader, Format22) {
  const ScratchFolder dir;
  spit(dir / "square.msh", square_v22);
  expect_square(read_gmsh(dir / "square.msh"));
}

TEST(GmshReader, Format41) {
  const ScratchFolder dir;
  spit(dir / "square.msh", square_v41);
  expect_square(read_gmsh(dir / "square.msh"));
}

/// Replace `from` by `to` in the 2.2 square, read it, and return the InputError.
InputError gmsh_error(const std::string& from, const std::string& to) {
  std::string text = square_v22;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const ScratchFolder dir;
  spit(dir / "bad.msh", text);
  try {
    read_gmsh(dir / "bad.msh");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "bad.msh").string());
    return e;
  }
  ADD_FAILURE() << "accepted";
  return InputError("", 0, "", "");
}

TEST(GmshReader, ErrorsNameTheLine) {
  // Line 27 is element 8: 10-30 is a diagonal, not a side of the 4 triangles.
  EXPECT_EQ(gmsh_error("8 1 2 4 3 30 40", "8 1 2 4 3 10 30").line(), 27);
  const InputError quad = gmsh_error("3 1 2 0 2 20 30", "3 3 2 0 2 10 20 30 40");
  EXPECT_EQ(quad.line(), 22);
  EXPECT_NE(std::string(quad.what()).find("element type 3"), std::string::npos);
  EXPECT_EQ(gmsh_error("7 2 2 7 1 40 10 50", "7 2 2 7 1 40 10 55").line(), 26);
  EXPECT_EQ(gmsh_error("2.2 0 8", "2.2 1 8").line(), 2);
  // Node 50 moved onto the bottom side: triangle 10-20-50 (line 23) has zero area.
  const InputError flat = gmsh_error("50 0.5 0.5 0", "50 0.5 0 0");
  EXPECT_EQ(flat.line(), 23);
  EXPECT_NE(std::string(flat.what()).find("degenerate"), std::string::npos);
  EXPECT_NE(std::string(gmsh_error("$EndElements", "").what()).find("unexpected end of file"),
            std::string::npos);
}

TEST(FreeFemReader, SmallMesh) {
  const ScratchFolder dir;
  // Two triangles, the second clockwise; labels negative or 0 as FreeFem allows.
  spit(dir / "two.msh", "4 2 3\n0 0 1\n1 0 -2\n1 1 0\n0 1 0\n"
                        "1 2 3 0\n1 4 3 5\n"
                        "2 1 1\n2 3 3\n3 4 0\n");
  const Mesh mesh = read_freefem_msh(dir / "two.msh");
  ASSERT_EQ(mesh.num_cells(), 2);
  EXPECT_GT(signed_double_area(mesh, 1), 0);
  EXPECT_EQ(mesh.subdomain, (std::vector<int>{1, 5}));
  EXPECT_EQ(mesh.vertex_ref, (std::vector<int>{1, 2, 0, 0}));
  ASSERT_EQ(mesh.facets.size(), 2u); // label 0 carries no reference
  EXPECT_EQ(mesh.facets[0].node[0], 0);
  EXPECT_EQ(mesh.facets[0].node[1], 1);
  EXPECT_EQ(mesh.facets[1].ref, 3);

  spit(dir / "bad.msh", "4 2 0\n0 0 1\n1 0 -2\n1 1 0\n0 1 0\n1 2 3 0\n1 4 9 5\n");
  try {
    read_freefem_msh(dir / "bad.msh");
    ADD_FAILURE() << "vertex 9 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 7);
  }

  // Node 3 moved to (2, 0): triangle 1 2 3 (line 6) has its three nodes on the x axis.
  spit(dir / "flat.msh", "4 2 0\n0 0 1\n1 0 -2\n2 0 0\n0 1 0\n1 2 3 0\n1 4 3 5\n");
  try {
    read_freefem_msh(dir / "flat.msh");
    ADD_FAILURE() << "degenerate triangle accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 6);
    EXPECT_NE(std::string(e.what()).find("degenerate"), std::string::npos);
  }
}

TEST(MeshFile, DispatchesOnExtensionAndContent) {
  const ScratchFolder dir;
  spit(dir / "g.msh", square_v22);
  EXPECT_EQ(read_mesh_file(dir / "g.msh").num_nodes(), 5);
  EXPECT_EQ(read_mesh_file(testing::shared_nopo("square3.msh")).num_nodes(), 16);
  EXPECT_EQ(read_mesh_file(testing::shared_nopo("square3.nopo")).num_nodes(), 16);
  EXPECT_THROW(read_mesh_file(dir / "g.vtk"), Error);
}

} // namespace
} // namespace sig

namespace sig {
namespace {

std::filesystem::path corpus(const std::string& name) {
  return std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / name;
}

using testing::error_of;

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  ASSERT_EQ(a.num_cells(), b.num_cells());
  for (int i = 0; i < a.num_nodes(); ++i)
    EXPECT_EQ(a.nodes[i], b.nodes[i]) << i;
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.subdomain, b.subdomain);
  EXPECT_EQ(a.vertex_ref, b.vertex_ref);
  ASSERT_EQ(a.facets.size(), b.facets.size());
  for (std::size_t e = 0; e < a.facets.size(); ++e) {
    EXPECT_EQ(a.facets[e].node[0], b.facets[e].node[0]);
    EXPECT_EQ(a.facets[e].node[1], b.facets[e].node[1]);
    EXPECT_EQ(a.facets[e].ref, b.facets[e].ref);
  }
}

// gmsh 4.8 saved the same square as 2.2 and 4.1, ASCII and binary (`gmsh -2 -bin`): the four
// files are one mesh, with its Physical Curve 3 (bottom), 2 (top) and Point 1.
TEST(GmshReader, BinaryFilesReadAsTheirAsciiTwins) {
  const Mesh ascii22 = read_gmsh(corpus("gmsh/square_v22_ascii.msh"));
  EXPECT_EQ(ascii22.num_cells(), 4);
  EXPECT_EQ(ascii22.references(), (std::vector<int>{1, 2, 3}));
  expect_same_mesh(ascii22, read_gmsh(corpus("gmsh/square_v22_binary.msh")));
  expect_same_mesh(ascii22, read_gmsh(corpus("gmsh/square_v41_ascii.msh")));
  expect_same_mesh(ascii22, read_gmsh(corpus("gmsh/square_v41_binary.msh")));
}

// A damaged binary file is refused with the file named, wherever it is cut.
TEST(GmshReader, TruncatedBinaryFilesAreRefused) {
  for (const char* name : {"gmsh/square_v22_binary.msh", "gmsh/square_v41_binary.msh"}) {
    const std::string bytes = testing::slurp(corpus(name));
    for (std::size_t cut = 0; cut + 1 < bytes.size(); cut += 7)
      EXPECT_NE(error_of([&] { parse_gmsh("cut.msh", bytes.substr(0, cut)); }).find("cut.msh"),
                std::string::npos)
          << name << " cut at " << cut;
  }
}

// Header counts are checked against the bytes left before anything is allocated: the error
// names the file and the line instead of std::bad_alloc.
TEST(GmshReader, CountsBeyondTheFileAreRefused) {
  std::string huge = square_v22;
  huge.replace(huge.find("$Nodes\n6"), 8, "$Nodes\n1000000000000");
  std::string message = error_of([&] { parse_gmsh("huge.msh", huge); });
  EXPECT_NE(message.find("huge.msh:10: 1000000000000 nodes: more than the 1e+08"),
            std::string::npos)
      << message;
  std::string big = square_v22;
  big.replace(big.find("$Nodes\n6"), 8, "$Nodes\n60000000");
  message = error_of([&] { parse_gmsh("big.msh", big); });
  EXPECT_NE(message.find("big.msh:10: 60000000 nodes announced, but the"), std::string::npos)
      << message;

  std::string block = square_v41; // a node block of 1e12 nodes
  const auto at = block.find("2 1 0 3\n30");
  ASSERT_NE(at, std::string::npos);
  block.replace(at, 7, "2 1 0 1000000000000");
  message = error_of([&] { parse_gmsh("block.msh", block); });
  EXPECT_NE(message.find("block.msh:"), std::string::npos) << message;
  EXPECT_NE(message.find("1000000000000 nodes"), std::string::npos) << message;

  message = error_of([&] { parse_freefem_msh("ff.msh", "2000000000 1 0\n0 0 0\n"); });
  EXPECT_NE(message.find("ff.msh:1: 2000000000 vertices: more than"), std::string::npos) << message;
  message = error_of([&] { parse_freefem_msh("ff.msh", "20000 1 0\n0 0 0\n1 0 0\n0 1 0\n"); });
  EXPECT_NE(message.find("ff.msh:1: 20000 vertices announced, but the"), std::string::npos)
      << message;
}

// P1 is the model: quadrangles and second-order elements are refused, saying so.
TEST(GmshReader, QuadranglesAndHigherOrderAreNamed) {
  std::string quad = square_v22;
  quad.replace(quad.find("3 1 2 0 2 20 30"), 15, "3 3 2 0 2 10 20 30 40");
  EXPECT_NE(error_of([&] { parse_gmsh("q.msh", quad); }).find("is a quadrangle: the model is P1"),
            std::string::npos);
  std::string p2 = square_v22;
  p2.replace(p2.find("3 1 2 0 2 20 30"), 15, "3 9 2 0 2 10 20 30 40 50 60");
  EXPECT_NE(error_of([&] { parse_gmsh("p2.msh", p2); }).find("second or higher order"),
            std::string::npos);
}

} // namespace
} // namespace sig
