// sig-dump's library half: a DS written by write_ds reads back into the same description, the
// DS magic tells DS files from NOPO, and the mesh summary counts what the mesh holds.
#include "post/dump.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

namespace sig {
namespace {

namespace fs = std::filesystem;

Ds sample_ds() {
  Ds ds("TAE", "assembled operators", "sig-assemble");
  ds.put_int("ndof", 10);
  ds.put("K_val", std::vector<double>{4.0, -1.0, 2.5, 1e-3, 7, 8, 9, 10, 11, 12}, {2, 5});
  ds.put_text("method", "alm");
  return ds;
}

TEST(Dump, DsFileIsRecognisedByItsMagic) {
  const testing::ScratchFolder dir;
  write_ds(dir / "case.tae", sample_ds());
  std::ofstream(dir / "case.nopo", std::ios::binary) << std::string("\0\0\0\x80 NOPO", 9);
  EXPECT_TRUE(is_ds_file(dir / "case.tae"));
  EXPECT_FALSE(is_ds_file(dir / "case.nopo"));

  const Ds back = read_ds(dir / "case.tae");
  const std::string json = dump_ds_json(back).dump(-1);
  EXPECT_EQ(json.find("{\"kind\":\"TAE\",\"title\":\"assembled operators\","
                      "\"creator\":\"sig-assemble\",\"date\":"),
            0u);
  EXPECT_NE(json.find("{\"name\":\"ndof\",\"type\":\"int64\",\"shape\":[1]}"), std::string::npos);
  EXPECT_NE(json.find("{\"name\":\"K_val\",\"type\":\"float64\",\"shape\":[2,5]}"),
            std::string::npos);
  EXPECT_NE(json.find("{\"name\":\"method\",\"type\":\"text\""), std::string::npos);
}

// The report scripts read DS files only through these values (postproc/sigreport/ds.py): every
// number must read back as the same double, integers as integers.
TEST(Dump, JsonValuesOfEveryOrTheNamedArrays) {
  Ds ds = sample_ds();
  ds.put("u", std::vector<double>{0.1, -2.0 / 3.0, std::numeric_limits<double>::quiet_NaN()});
  const std::string all = dump_ds_json(ds, {.all = true, .names = {}}).dump(-1);
  EXPECT_NE(all.find("{\"name\":\"ndof\",\"type\":\"int64\",\"shape\":[1],\"values\":[10]}"),
            std::string::npos);
  EXPECT_NE(all.find("\"shape\":[2,5],\"values\":[4,-1,2.5,0.001,7,8,9,10,11,12]}"),
            std::string::npos);
  EXPECT_NE(all.find("\"values\":\"alm\""), std::string::npos);
  EXPECT_NE(all.find("\"values\":[0.1,-0.6666666666666666,null]"), std::string::npos);

  const std::string some = dump_ds_json(ds, {.all = false, .names = {"method"}}).dump(-1);
  EXPECT_NE(some.find("\"values\":\"alm\""), std::string::npos);
  EXPECT_EQ(some.find("\"values\":["), std::string::npos);
  EXPECT_EQ(dump_ds_json(ds).dump(-1).find("values"), std::string::npos);
  EXPECT_THROW(dump_ds_json(ds, {.all = false, .names = {"lambda"}}), Error);
}

TEST(Dump, TextShowsHeaderShapesAndFirstValues) {
  const std::string text = dump_ds_text(sample_ds(), 3);
  EXPECT_NE(text.find("DS TAE"), std::string::npos);
  EXPECT_NE(text.find("assembled operators"), std::string::npos);
  EXPECT_NE(text.find("sig-assemble"), std::string::npos);
  EXPECT_NE(text.find("float64 [2 x 5]  4 -1 2.5 ..."), std::string::npos);
  EXPECT_NE(text.find("int64 [1]  10\n"), std::string::npos);
  EXPECT_NE(text.find("\"alm\""), std::string::npos);
}

TEST(Dump, MeshSummaryCountsTheMesh) {
  const Mesh mesh = test::small_mesh();
  const std::string json = dump_mesh_json(mesh, "small").dump(-1);
  EXPECT_EQ(json, "{\"kind\":\"NOPO\",\"title\":\"small\",\"nodes\":5,\"triangles\":3,"
                  "\"boundary_edges\":5,\"references\":[1,2,3,4],\"subdomains\":[1,2]}");
  // With its values: the mesh itself, numbered from 1.
  const Json full = dump_mesh_json(mesh, "small", true);
  const std::string values = full.dump(-1);
  std::string coordinates = "\"coordinates\":[";
  for (int i = 0; i < mesh.num_nodes(); ++i)
    coordinates += Json(mesh.nodes[i].x()).dump(-1) + "," + Json(mesh.nodes[i].y()).dump(-1) +
                   (i + 1 < mesh.num_nodes() ? "," : "]");
  EXPECT_NE(values.find(coordinates), std::string::npos) << values;
  const auto& t = mesh.cells.front();
  EXPECT_NE(values.find("\"triangle_nodes\":[" + std::to_string(t[0] + 1) + "," +
                        std::to_string(t[1] + 1) + "," + std::to_string(t[2] + 1) + ","),
            std::string::npos)
      << values;
  const Facet& e = mesh.facets.front();
  EXPECT_NE(values.find("\"edges\":[" + std::to_string(e.node[0] + 1) + "," +
                        std::to_string(e.node[1] + 1) + "," + std::to_string(e.ref) + ","),
            std::string::npos)
      << values;
  const std::string text = dump_mesh_text(mesh, "small");
  EXPECT_NE(text.find("3 (2 edges, 3 nodes)"), std::string::npos);
  EXPECT_NE(text.find("2 (2 triangles)"), std::string::npos);
  EXPECT_NE(text.find("[0, 2] x [0, 1]"), std::string::npos);
}

} // namespace
} // namespace sig
