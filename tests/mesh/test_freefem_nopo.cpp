// Interoperability with the FreeFem++ installed on this machine (skipped when it is absent):
// FreeFem writes meshes as NOPO and .msh, we read both and compare; FreeFem reads a NOPO file we
// wrote and saves it as .msh, which must be our mesh.
#include "mesh/generators.hpp"
#include "mesh/nopo.hpp"
#include "mesh_testing.hpp"

#include <cstdlib>

namespace sig {
namespace {

using testing::ScratchFolder;

bool have_freefem() {
  return std::system("command -v FreeFem++ > /dev/null 2>&1") == 0;
}

void run_freefem(const ScratchFolder& dir, const std::string& script) {
  testing::spit(dir / "x.edp", script);
  const std::string command =
      "cd '" + dir.path().string() + "' && FreeFem++ -nw -v 0 x.edp > freefem.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << testing::slurp(dir / "freefem.log");
}

TEST(FreeFemInterop, FreeFemNopoEqualsItsMsh) {
  if (!have_freefem()) GTEST_SKIP() << "FreeFem++ not installed";
  const ScratchFolder dir;
  run_freefem(dir, R"(
mesh Th = square(5, 7, [2*x, 3*y]);
savemesh(Th, "square.nopo"); savemesh(Th, "square.msh");
border C(t=0, 2*pi) { x=cos(t); y=sin(t); label=5; }
mesh Td = buildmesh(C(20));
savemesh(Td, "disc.nopo"); savemesh(Td, "disc.msh");
)");
  for (const std::string name : {"square", "disc"}) {
    SCOPED_TRACE(name);
    const NopoFile file = read_nopo_file(dir / (name + ".nopo"));
    testing::expect_mesh_matches_freefem(file.mesh,
                                         testing::read_raw_freefem(dir / (name + ".msh")), 1e-6);
    NopoWriteOptions same;
    same.text = file.text;
    same.ndsr = file.nop2[1];
    EXPECT_TRUE(encode_nopo(file.mesh,
                            file.layout.marker_bytes == 8 ? NopoVariant::ff64 : NopoVariant::i4r4,
                            same) == testing::slurp(dir / (name + ".nopo")));
  }
}

TEST(FreeFemInterop, FreeFemReadsOurNopo) {
  if (!have_freefem()) GTEST_SKIP() << "FreeFem++ not installed";
  const ScratchFolder dir;
  const Mesh ours = ring({0, 10}, 9, 10, 32, {3, {}, {}});
  write_nopo(dir / "ours.nopo", ours, NopoVariant::ff64, "ring for FreeFem", "test_mesh");
  run_freefem(dir, R"(
mesh Th = readmesh("ours.nopo");
savemesh(Th, "ours.msh");
)");
  const auto raw = testing::read_raw_freefem(dir / "ours.msh");
  ASSERT_EQ(raw.x.size(), static_cast<std::size_t>(ours.num_nodes()));
  for (int i = 0; i < ours.num_nodes(); ++i) {
    EXPECT_NEAR(raw.x[i], ours.nodes[i].x(), 1e-5);
    EXPECT_NEAR(raw.y[i], ours.nodes[i].y(), 1e-5);
    EXPECT_EQ(raw.vertex_label[i], ours.vertex_ref[i]);
  }
  ASSERT_EQ(raw.cells.size(), ours.cells.size());
  for (int t = 0; t < ours.num_cells(); ++t) {
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(raw.cells[t][j], ours.cells[t][j] + 1);
  }
  std::map<std::uint64_t, long> edges;
  for (const auto& e : ours.facets)
    edges[edge_key(e.node[0], e.node[1])] = e.ref;
  EXPECT_EQ(raw.edge_label, edges);
}

} // namespace
} // namespace sig
