// The MESH card: generators and files, and the errors a user sees.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "mesh/mesh_card.hpp"
#include "mesh_testing.hpp"

namespace sig {
namespace {

Mesh from(const std::string& line, const std::filesystem::path& folder = ".") {
  const Datafile datafile = Datafile::parse(line + "\n", "deck.dat");
  return mesh_from_card(datafile.require("MESH"), folder);
}

/// The field an invalid card is blamed on.
std::string blamed_field(const std::string& line, const std::filesystem::path& folder = ".") {
  try {
    from(line, folder);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "deck.dat");
    EXPECT_EQ(e.line(), 1);
    return e.field();
  }
  ADD_FAILURE() << "accepted: " << line;
  return "";
}

TEST(MeshCard, Generators) {
  EXPECT_EQ(from("MESH generator=ring centre=0,10 r_in=9 r_out=10 N=16 layers=3").num_nodes(), 48);
  const Mesh rect = from("MESH generator=rectangle lx=5 ly=1 nx=5 ny=1 refs=3,1,2,1");
  EXPECT_EQ(rect.num_cells(), 10);
  EXPECT_EQ(rect.facets_with_ref(1).size(), 2u);
  EXPECT_EQ(from("MESH generator=square lx=1 nx=3").num_nodes(), 16);
  if (!testing::have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  const Mesh hd = from("MESH generator=half-disc R=1 N=8");
  EXPECT_EQ(hd.nodes_with_ref(3).size(), 9u);
}

// centre= is the spelling of every card; MESH's old center= reads the same ring, the two together
// are refused.
TEST(MeshCard, CenterIsTheOldSpellingOfCentre) {
  const Mesh canonical = from("MESH generator=ring centre=3,7 r_in=9 r_out=10 N=16 layers=3");
  const Mesh old = from("MESH generator=ring center=3,7 r_in=9 r_out=10 N=16 layers=3");
  const Mesh origin = from("MESH generator=ring r_in=9 r_out=10 N=16 layers=3");
  ASSERT_EQ(old.num_nodes(), canonical.num_nodes());
  for (int i = 0; i < canonical.num_nodes(); ++i) {
    EXPECT_EQ(old.nodes[i], canonical.nodes[i]) << "node " << i;
    EXPECT_LT((canonical.nodes[i] - origin.nodes[i] - Eigen::Vector2d(3, 7)).norm(), 1e-12)
        << "node " << i;
  }
  EXPECT_EQ(blamed_field("MESH generator=ring centre=3,7 center=3,7 r_in=9 r_out=10 N=16"),
            "center");
}

TEST(MeshCard, Files) {
  const std::filesystem::path legacy = std::filesystem::path(SIG_SOURCE_DIR) / "meshes" / "legacy";
  EXPECT_EQ(from("MESH file=square3.nopo", legacy).num_cells(), 18);
  EXPECT_EQ(from("MESH file=tworeg.msh", legacy).num_cells(), 16);
  EXPECT_EQ(blamed_field("MESH file=nothing.nopo", legacy), "file");
  EXPECT_EQ(blamed_field("MESH file=square3.edp", legacy), "file");
}

TEST(MeshCard, InvalidFieldsAreBlamed) {
  EXPECT_EQ(blamed_field("MESH generator=half_disc R=8 N=15"), "N");
  EXPECT_EQ(blamed_field("MESH generator=half_disc R=8 N=2"), "N");
  EXPECT_EQ(blamed_field("MESH generator=half_disc R=-1 N=16"), "R");
  EXPECT_EQ(blamed_field("MESH generator=disc R=1 N=18"), "N");
  EXPECT_EQ(blamed_field("MESH generator=ring r_in=10 r_out=9 N=16"), "r_in");
  EXPECT_EQ(blamed_field("MESH generator=ring r_in=9 r_out=10 N=16 lx=3"), "lx");
  EXPECT_EQ(blamed_field("MESH generator=ring r_in=9 r_out=10 N=16 centre=1"), "centre");
  EXPECT_EQ(blamed_field("MESH generator=ring r_in=9 r_out=10 N=16 center=1"), "center");
  EXPECT_EQ(blamed_field("MESH generator=rectangle lx=1 ly=1 nx=1 ny=1 refs=1,2"), "refs");
  EXPECT_EQ(blamed_field("MESH generator=square lx=1 nx=0"), "nx");
  EXPECT_EQ(blamed_field("MESH generator=torus"), "generator");
  EXPECT_EQ(blamed_field("MESH generator=square lx=1 nx=2 file=a.nopo"), "file");
}

} // namespace
} // namespace sig
