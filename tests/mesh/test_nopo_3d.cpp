// NOPO in 3D (NDIM = 3, MODULEF's tetrahedron NCGE = 5 with its face references, INING = 1):
// a gmsh cube written and read back in the three layouts.
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sig {
namespace {

Mesh cube() {
  Mesh mesh = read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" /
                        "gmsh" / "box_v41_ascii.msh");
  mesh.vertex_ref[0] = 9; // a vertex reference too
  return mesh;
}

TEST(Nopo3d, RoundTripsInEveryLayout) {
  const Mesh mesh = cube();
  for (const NopoVariant variant : {NopoVariant::i8r8, NopoVariant::ff64, NopoVariant::i4r4}) {
    NopoWriteOptions options;
    options.text = {"a cube", "", "test"};
    const NopoFile file = parse_nopo_file("cube.nopo", encode_nopo(mesh, variant, options));
    const Mesh& back = file.mesh;
    EXPECT_EQ(file.nop2[0], 3);                // NDIM
    EXPECT_EQ(file.nop2[7], 0);                // NTRI
    EXPECT_EQ(file.nop2[9], mesh.num_cells()); // NTET
    EXPECT_EQ(file.nop2[1], 9);                // NDSR, the largest reference
    EXPECT_EQ(back.dim, 3);
    ASSERT_EQ(back.num_nodes(), mesh.num_nodes());
    const double tolerance = variant == NopoVariant::i8r8 ? 0 : 1e-7; // 4-byte reals
    for (int i = 0; i < mesh.num_nodes(); ++i)
      EXPECT_LE((back.nodes[i] - mesh.nodes[i]).norm(), tolerance) << i;
    EXPECT_EQ(back.cells, mesh.cells);
    EXPECT_EQ(back.subdomain, mesh.subdomain);
    EXPECT_EQ(back.vertex_ref, mesh.vertex_ref);
    // The faces come back oriented outward, as the reader orients them, in the order of the
    // tetrahedra that carry them.
    ASSERT_EQ(back.facets.size(), mesh.facets.size());
    for (int ref : {1, 2, 3})
      EXPECT_EQ(back.facets_with_ref(ref).size(), mesh.facets_with_ref(ref).size()) << ref;
    for (const Facet& f : back.facets) {
      bool found = false;
      for (const Facet& g : mesh.facets)
        found = found || (g.node == f.node && g.ref == f.ref);
      EXPECT_TRUE(found) << f.node[0] << " " << f.node[1] << " " << f.node[2];
    }
  }
}

TEST(Nopo3d, WrittenTwiceTheSameBytes) {
  const Mesh mesh = cube();
  NopoWriteOptions options;
  const std::string bytes = encode_nopo(mesh, NopoVariant::i8r8, options);
  EXPECT_EQ(encode_nopo(parse_nopo_file("c.nopo", bytes).mesh, NopoVariant::i8r8, options).size(),
            bytes.size());
}

} // namespace
} // namespace sig
