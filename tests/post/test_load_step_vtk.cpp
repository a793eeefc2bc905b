// A load-stepped case for ParaView: every state of case.b's step_u becomes one .vtu whose
// displacement and contact pressure are the DS values (read back through VTK's own reader), the
// .pvd lists exactly those states with their load factors, a failed last step (fewer states than
// load steps) is left out, and shapes that do not fit, or NaN, are refused. The sig-post stage
// writes the series for such a case.b.
#include "post/load_step_vtk.hpp"

#include "core/error.hpp"
#include "mesh/nopo.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"
#include "stage_scope.hpp"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

namespace sig {
namespace {

namespace fs = std::filesystem;

// `steps` load steps of which the first `kept` converged: state s (0-based) has
// u = (s + 1) (0.1 x, -0.2 y), multipliers (s + 1) (1, 2, 3) and node 5 alone in contact.
Ds load_stepped(const Mesh& mesh, int steps, int kept) {
  Ds b("B", "stepped", "test");
  std::vector<double> load, u, multiplier;
  std::vector<std::int64_t> status;
  for (int s = 0; s < steps; ++s)
    load.push_back((s + 1.0) / steps);
  for (int s = 0; s < kept; ++s) {
    for (const Point& x : mesh.nodes)
      u.insert(u.end(), {(s + 1) * 0.1 * x.x(), -(s + 1) * 0.2 * x.y()});
    multiplier.insert(multiplier.end(), {s + 1.0, 2.0 * (s + 1), 3.0 * (s + 1)});
    status.insert(status.end(), {0, 2, 0}); // CU
  }
  const auto ndof = static_cast<std::int64_t>(2 * mesh.num_nodes());
  b.put("step_load", load);
  b.put("step_u", u, {kept, ndof});
  b.put("step_multiplier", multiplier, {kept, 3});
  b.put("step_normal_status", status, {kept, 3});
  b.put("u", std::vector<double>(u.end() - ndof, u.end()));
  b.put_text("method", "pdas");
  return b;
}

/// (time, file) of every DataSet of a .pvd, in order.
std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& pvd) {
  std::stringstream text;
  text << std::ifstream(pvd).rdbuf();
  const std::string xml = text.str();
  const std::regex dataset(R"re(timestep="([^"]+)"[^>]*file="([^"]+)")re");
  std::vector<std::pair<double, std::string>> entries;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), dataset);
       it != std::sregex_iterator(); ++it)
    entries.emplace_back(std::stod((*it)[1]), (*it)[2]);
  return entries;
}

class LoadStepVtk : public ::testing::Test {
protected:
  const testing::ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
};

TEST_F(LoadStepVtk, StatesWrittenAreStatesRead) {
  const Mesh mesh = test::small_mesh();
  const Ds cont = test::bottom_contact();
  const Ds b = load_stepped(mesh, 3, 3);
  const auto files =
      write_load_step_vtk(dir_, "ring", mesh, test::two_materials(0.3), b, &cont, {{"title", "t"}});
  ASSERT_EQ(files.size(), 4u);
  const auto entries = pvd_entries(files[0]);
  ASSERT_EQ(entries.size(), 3u);
  const std::vector<double> weight = cont.reals("weight");
  for (int s = 0; s < 3; ++s) {
    EXPECT_DOUBLE_EQ(entries[s].first, (s + 1) / 3.0); // pseudo-time = load factor
    EXPECT_EQ(dir_ / entries[s].second, files[s + 1]);
    const auto grid = test::read_vtu(files[s + 1]);
    ASSERT_EQ(grid->GetNumberOfPoints(), mesh.num_nodes());
    vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
    vtkDataArray* pressure = grid->GetPointData()->GetArray("contact_pressure");
    vtkDataArray* status = grid->GetPointData()->GetArray("contact_status");
    ASSERT_NE(u, nullptr);
    ASSERT_NE(pressure, nullptr);
    ASSERT_NE(status, nullptr);
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      EXPECT_DOUBLE_EQ(u->GetComponent(i, 0), (s + 1) * 0.1 * mesh.nodes[i].x());
      EXPECT_DOUBLE_EQ(u->GetComponent(i, 1), -(s + 1) * 0.2 * mesh.nodes[i].y());
    }
    // Contact nodes 1, 5, 2 (0-based 0, 4, 1): pressure = multiplier / weight.
    const int nodes[3] = {0, 4, 1};
    for (int k = 0; k < 3; ++k)
      EXPECT_DOUBLE_EQ(pressure->GetComponent(nodes[k], 0), (k + 1.0) * (s + 1) / weight[k]);
    EXPECT_EQ(pressure->GetComponent(3, 0), 0.0); // off Gamma3
    EXPECT_EQ(status->GetComponent(4, 0), 1.0);
    EXPECT_EQ(status->GetComponent(0, 0), 0.0);
    // The statuses as their codes: CU (2) at node 5, no friction anywhere.
    vtkDataArray* normal = grid->GetPointData()->GetArray("normal_status");
    vtkDataArray* friction = grid->GetPointData()->GetArray("friction_status");
    ASSERT_NE(normal, nullptr);
    ASSERT_NE(friction, nullptr);
    EXPECT_EQ(normal->GetComponent(4, 0), 2.0);
    EXPECT_EQ(normal->GetComponent(0, 0), 0.0);
    EXPECT_EQ(friction->GetComponent(4, 0), 0.0);
    ASSERT_NE(grid->GetPointData()->GetArray("tangential_pressure"), nullptr);
  }
}

TEST_F(LoadStepVtk, FailedLastStepIsLeftOutAndNoContactMeansNoPressure) {
  const Mesh mesh = test::small_mesh();
  const Ds b = load_stepped(mesh, 4, 2); // steps 3 and 4 never converged
  EXPECT_EQ(load_step_count(b, mesh), 2u);
  const auto files =
      write_load_step_vtk(dir_, "ring", mesh, test::two_materials(0.3), b, nullptr, {});
  ASSERT_EQ(files.size(), 3u);
  const auto entries = pvd_entries(files[0]);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_DOUBLE_EQ(entries[1].first, 0.5);
  const auto grid = test::read_vtu(files[2]);
  EXPECT_EQ(grid->GetPointData()->GetArray("contact_pressure"), nullptr);
  EXPECT_NE(grid->GetPointData()->GetArray("displacement"), nullptr);
}

TEST_F(LoadStepVtk, RefusesWrongShapesAndNaN) {
  const Mesh mesh = test::small_mesh();
  const Ds cont = test::bottom_contact();
  Ds b = load_stepped(mesh, 2, 2);
  b.put("step_load", std::vector<double>{1.0}); // two states, one load step
  EXPECT_THROW(write_load_step_vtk(dir_, "x", mesh, test::two_materials(0.3), b, &cont, {}), Error);
  b = load_stepped(mesh, 2, 2);
  b.put("step_normal_status", std::vector<std::int64_t>{0, 2, 0, 0, 2}, {1, 5}); // not 2 x 3
  EXPECT_THROW(write_load_step_vtk(dir_, "x", mesh, test::two_materials(0.3), b, &cont, {}), Error);
  b = load_stepped(mesh, 2, 2);
  std::vector<double> u = b.reals("step_u");
  u[7] = std::numeric_limits<double>::quiet_NaN();
  b.put("step_u", u, b.shape("step_u"));
  EXPECT_THROW(write_load_step_vtk(dir_, "x", mesh, test::two_materials(0.3), b, &cont, {}), Error);
  EXPECT_TRUE(fs::is_empty(dir_)); // refused before any file was written
}

TEST_F(LoadStepVtk, SigPostWritesOneStatePerLoadStep) {
  const fs::path exe = fs::path(SIG_BINARY_DIR) / "bin" / "sig-post";
  if (!fs::exists(exe)) GTEST_SKIP() << "no " << exe;
  const Mesh mesh = test::small_mesh();
  std::ofstream(dir_ / "block.dat") << "TITLE stepped block\nOUTPUT vtk=yes\n";
  {
    const testing::StageScope stage(dir_, dir_ / "block.dat", "mesh");
    write_nopo(dir_ / "case.nopo", mesh, NopoVariant::i8r8, "block", "test");
  }
  {
    const testing::StageScope stage(dir_, dir_ / "block.dat", "material");
    write_mili(dir_ / "case.mili", test::two_materials(0.3), "block");
  }
  Ds b = load_stepped(mesh, 3, 3);
  b.put_text("linear", "umfpack");
  b.put_int("converged", 1);
  b.put_int("iterations", 6);
  b.put_int("dofs", 10);
  b.put_int("finite_strain", 1);
  {
    const testing::StageScope stage(dir_, dir_ / "block.dat", "solve");
    write_ds(dir_ / "case.b", b);
  }
  const std::string command = exe.string() + " " + (dir_ / "block.dat").string() + " -o " +
                              dir_.string() + " > " + (dir_ / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const auto entries = pvd_entries(dir_ / "block.pvd");
  ASSERT_EQ(entries.size(), 3u);
  for (int s = 0; s < 3; ++s)
    EXPECT_TRUE(fs::exists(dir_ / entries[s].second)) << entries[s].second;
  EXPECT_DOUBLE_EQ(entries[2].first, 1.0);
  EXPECT_FALSE(fs::exists(dir_ / "block_0003.vtu"));
  EXPECT_TRUE(fs::exists(dir_ / "summary.json"));
}

} // namespace
} // namespace sig
