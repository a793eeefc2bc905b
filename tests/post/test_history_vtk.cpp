// A dynamic case for ParaView: every state of a DS HIST becomes one .vtu whose displacement and
// velocity are the DS values (read back through VTK's own reader), the .pvd lists them with their
// times, and a DS whose shapes do not fit the mesh, or that holds NaN, is refused. A march with
// contact (contact_node, pressure) adds contact_pressure: the DS value on Gamma3, 0 elsewhere.
#include "post/history_vtk.hpp"

#include "core/error.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace sig {
namespace {

namespace fs = std::filesystem;

// Two states of the small mesh: state s has u = s (0.1 x, -0.2 y) and v = (s + 1, 2 s - 1).
Ds two_states(const Mesh& mesh) {
  Ds hist("HIST", "two states", "test");
  std::vector<double> u, v;
  for (int s = 0; s < 2; ++s)
    for (const Point& x : mesh.nodes) {
      u.insert(u.end(), {s * 0.1 * x.x(), -s * 0.2 * x.y()});
      v.insert(v.end(), {s + 1.0, 2.0 * s - 1.0});
    }
  const auto ndof = static_cast<std::int64_t>(2 * mesh.num_nodes());
  hist.put("output_time", std::vector<double>{0.0, 0.25});
  hist.put("u", u, {2, ndof});
  hist.put("v", v, {2, ndof});
  hist.put_text("scheme", "midpoint");
  return hist;
}

class HistoryVtk : public ::testing::Test {
protected:
  const testing::ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
};

TEST_F(HistoryVtk, OneVtuPerStateWithDisplacementAndVelocity) {
  const Mesh mesh = test::small_mesh();
  const auto files = write_history_vtk(dir_, "disc", mesh, test::two_materials(0.35),
                                       two_states(mesh), {{"title", "t"}});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0], dir_ / "disc.pvd");
  std::stringstream pvd;
  pvd << std::ifstream(files[0]).rdbuf();
  EXPECT_NE(pvd.str().find("disc_0000.vtu"), std::string::npos);
  EXPECT_NE(pvd.str().find("disc_0001.vtu"), std::string::npos);
  EXPECT_NE(pvd.str().find("0.25"), std::string::npos);
  for (int s = 0; s < 2; ++s) {
    const auto grid = test::read_vtu(files[s + 1]);
    ASSERT_EQ(grid->GetNumberOfPoints(), mesh.num_nodes());
    vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
    vtkDataArray* v = grid->GetPointData()->GetArray("velocity");
    ASSERT_NE(u, nullptr);
    ASSERT_NE(v, nullptr);
    ASSERT_EQ(v->GetNumberOfComponents(), 3);
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const Eigen::Vector2d& x = mesh.nodes[i];
      EXPECT_DOUBLE_EQ(u->GetComponent(i, 0), s * 0.1 * x.x());
      EXPECT_DOUBLE_EQ(u->GetComponent(i, 1), -s * 0.2 * x.y());
      EXPECT_DOUBLE_EQ(v->GetComponent(i, 0), s + 1.0);
      EXPECT_DOUBLE_EQ(v->GetComponent(i, 1), 2.0 * s - 1.0);
      EXPECT_EQ(v->GetComponent(i, 2), 0.0);
    }
  }
}

TEST_F(HistoryVtk, RefusesWrongShapesAndNaN) {
  const Mesh mesh = test::small_mesh();
  Ds hist = two_states(mesh);
  hist.put("output_time", std::vector<double>{0.0}); // two states in u, one time
  EXPECT_THROW(write_history_vtk(dir_, "x", mesh, test::two_materials(0.35), hist, {}), Error);
  hist = two_states(mesh);
  std::vector<double> v = hist.reals("v");
  v[3] = std::numeric_limits<double>::quiet_NaN();
  hist.put("v", v, hist.shape("u"));
  EXPECT_THROW(write_history_vtk(dir_, "x", mesh, test::two_materials(0.35), hist, {}), Error);
}

// Contact on the bottom edge (nodes 1, 5, 2 in the 1-based numbering of the DS): state s has
// pressure (10 s + 1, 10 s + 2, 10 s + 3) there.
Ds with_contact(const Mesh& mesh) {
  Ds hist = two_states(mesh);
  hist.put("contact_node", std::vector<std::int64_t>{1, 5, 2});
  hist.put("pressure", std::vector<double>{1, 2, 3, 11, 12, 13}, {2, 3});
  return hist;
}

double point_value(const fs::path& vtu, const char* name, int node) {
  const auto grid = test::read_vtu(vtu);
  vtkDataArray* array = grid->GetPointData()->GetArray(name);
  if (array == nullptr) return std::numeric_limits<double>::quiet_NaN();
  return array->GetComponent(node, 0);
}

TEST_F(HistoryVtk, ContactPressureOnGamma3ZeroElsewhere) {
  const Mesh mesh = test::small_mesh();
  const auto files =
      write_history_vtk(dir_, "ball", mesh, test::two_materials(0.35), with_contact(mesh), {});
  ASSERT_EQ(files.size(), 3u);
  for (int s = 0; s < 2; ++s) {
    // 0-based nodes 0, 4, 1 carry the DS's 1-based contact nodes 1, 5, 2.
    EXPECT_DOUBLE_EQ(point_value(files[s + 1], "contact_pressure", 0), 10.0 * s + 1);
    EXPECT_DOUBLE_EQ(point_value(files[s + 1], "contact_pressure", 4), 10.0 * s + 2);
    EXPECT_DOUBLE_EQ(point_value(files[s + 1], "contact_pressure", 1), 10.0 * s + 3);
    EXPECT_EQ(point_value(files[s + 1], "contact_pressure", 2), 0.0);
    EXPECT_EQ(point_value(files[s + 1], "contact_pressure", 3), 0.0);
    EXPECT_DOUBLE_EQ(point_value(files[s + 1], "velocity", 0), s + 1.0); // kept as before
  }
}

TEST_F(HistoryVtk, NoContactPressureWithoutContactArrays) {
  const Mesh mesh = test::small_mesh();
  const auto files =
      write_history_vtk(dir_, "disc", mesh, test::two_materials(0.35), two_states(mesh), {});
  EXPECT_TRUE(std::isnan(point_value(files[1], "contact_pressure", 0)));
}

TEST_F(HistoryVtk, RefusesBadContactArrays) {
  const Mesh mesh = test::small_mesh();
  Ds hist = with_contact(mesh);
  hist.put("contact_node", std::vector<std::int64_t>{1, 6, 2}); // the mesh has 5 nodes
  EXPECT_THROW(write_history_vtk(dir_, "x", mesh, test::two_materials(0.35), hist, {}), Error);
  hist = with_contact(mesh);
  hist.put("pressure", std::vector<double>{1, 2, 3}, {1, 3}); // one state of two
  EXPECT_THROW(write_history_vtk(dir_, "x", mesh, test::two_materials(0.35), hist, {}), Error);
  hist = with_contact(mesh);
  hist.put("pressure",
           std::vector<double>{1, 2, 3, 11, std::numeric_limits<double>::infinity(), 13}, {2, 3});
  EXPECT_THROW(write_history_vtk(dir_, "x", mesh, test::two_materials(0.35), hist, {}), Error);
}

} // namespace
} // namespace sig
