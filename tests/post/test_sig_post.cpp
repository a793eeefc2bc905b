// The sig-post stage end to end on a hand-made case: the files it promises, and the refusal of a
// displacement holding NaN. Skipped when the executable has not been built.
#include "core/ds.hpp"
#include "material/mili.hpp"
#include "mesh/nopo.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"
#include "stage_scope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sig {
namespace {

namespace fs = std::filesystem;

class SigPost : public ::testing::Test {
protected:
  void SetUp() override {
    exe_ = fs::path(SIG_BINARY_DIR) / "bin" / "sig-post";
    if (!fs::exists(exe_)) GTEST_SKIP() << "no " << exe_;
    std::ofstream(dir_ / "block.dat") << "TITLE three triangles\nOUTPUT vtk=yes\n";
    {
      const testing::StageScope mesh(dir_, dir_ / "block.dat", "mesh");
      write_nopo(dir_ / "case.nopo", test::small_mesh(), NopoVariant::i8r8, "block", "test");
    }
    const testing::StageScope material(dir_, dir_ / "block.dat", "material");
    write_mili(dir_ / "case.mili", test::two_materials(0.3), "block");
  }
  void write_solution(const std::vector<double>& u) {
    Ds b("B", "block", "test");
    b.put("u", u, {}, Finite::not_required); // a damaged case.b, as an editor may make it
    b.put_text("method", "linear");
    b.put_text("linear", "cholmod");
    b.put_int("converged", 1);
    b.put_int("iterations", 0);
    b.put_int("dofs", 10);
    b.put_scalar("time_solve", 0.5);
    const testing::StageScope solve(dir_, dir_ / "block.dat", "solve");
    write_ds(dir_ / "case.b", b);
  }
  int run(std::string& output) {
    const std::string command = exe_.string() + " " + (dir_ / "block.dat").string() + " -o " +
                                dir_.string() + " > " + (dir_ / "log").string() + " 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(dir_ / "log");
    std::stringstream text;
    text << in.rdbuf();
    output = text.str();
    return status;
  }
  const testing::ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
  fs::path exe_;
};

TEST_F(SigPost, WritesParaViewFilesAndSummary) {
  write_solution(std::vector<double>(10, 0.01));
  std::string output;
  ASSERT_EQ(run(output), 0) << output;
  EXPECT_TRUE(fs::exists(dir_ / "block.pvd"));
  EXPECT_TRUE(fs::exists(dir_ / "block_0000.vtu"));
  EXPECT_TRUE(fs::exists(dir_ / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "contact.csv"));
  EXPECT_NE(output.find("block.pvd"), std::string::npos);
  std::ifstream in(dir_ / "summary.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_NE(json.str().find("\"title\": \"three triangles\""), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"nodes\": 5"), std::string::npos);
}

TEST_F(SigPost, RefusesNanWithTheDof) {
  std::vector<double> u(10, 0.0);
  u[6] = std::nan("");
  write_solution(u);
  std::string output;
  EXPECT_NE(run(output), 0);
  EXPECT_NE(output.find("case.b: array 'u': value 7 of 10 is NaN"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "block.pvd"));
}

} // namespace
} // namespace sig
