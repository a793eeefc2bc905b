// ParaView output: what write_vtu writes is what VTK's own reader reads back (points, cells,
// point, cell and field data), the collection lists the steps, and nothing half-written is left.
#include "post/vtk_writer.hpp"

#include "core/error.hpp"
#include "post_test_mesh.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sig {
namespace {

namespace fs = std::filesystem;

class VtkWriter : public ::testing::Test {
protected:
  const testing::ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
};

// Each compression (OUTPUT compression=) is named in the file's header and read back bit for bit.
TEST_F(VtkWriter, EveryCompressionRoundTrips) {
  const Mesh mesh = test::small_mesh();
  std::vector<double> displacement;
  for (int i = 0; i < mesh.num_nodes(); ++i)
    displacement.insert(displacement.end(), {0.1 * i + 1e-17, -0.2 * i, 0.0});
  const std::vector<std::pair<VtkCompression, std::string>> kinds = {
      {VtkCompression::zlib, "vtkZLibDataCompressor"},
      {VtkCompression::lz4, "vtkLZ4DataCompressor"},
      {VtkCompression::none, ""}};
  for (const auto& [compression, compressor] : kinds) {
    const fs::path path = dir_ / ("case_" + std::to_string(static_cast<int>(compression)) + ".vtu");
    write_vtu(path, mesh, {{"displacement", 3, displacement}}, {}, {{"title", "t"}}, {},
              compression);
    std::ifstream in(path, std::ios::binary);
    std::string header(512, '\0');
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    header = header.substr(0, header.find("<UnstructuredGrid"));
    if (compressor.empty())
      EXPECT_EQ(header.find("compressor="), std::string::npos) << header;
    else
      EXPECT_NE(header.find("compressor=\"" + compressor + "\""), std::string::npos) << header;
    const auto grid = test::read_vtu(path);
    vtkDataArray* d = grid->GetPointData()->GetArray("displacement");
    ASSERT_NE(d, nullptr) << compressor;
    for (int i = 0; i < mesh.num_nodes(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(d->GetComponent(i, c), displacement[3 * i + c]) << compressor;
  }
}

TEST_F(VtkWriter, RoundTripThroughVtkReader) {
  const Mesh mesh = test::small_mesh();
  std::vector<double> displacement;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    displacement.insert(displacement.end(), {0.1 * i, -0.2 * i, 0.0});
  }
  const std::vector<VtkField> point = {{"displacement", 3, displacement},
                                       {"contact_status", 1, {1, 1, 0, 0, 1}, true}};
  const std::vector<VtkField> cell = {{"von_mises", 1, {1.5, 2.5, 3.25}},
                                      {"subdomain", 1, {1, 2, 2}, true}};
  const fs::path path = dir_ / "case_0000.vtu";
  write_vtu(path, mesh, point, cell, {{"title", "two-sub-domain rectangle, E = 2 GPa"}},
            {{"load_factor", 0.25}});

  const auto grid = test::read_vtu(path);
  ASSERT_EQ(grid->GetNumberOfPoints(), mesh.num_nodes());
  ASSERT_EQ(grid->GetNumberOfCells(), mesh.num_cells());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    EXPECT_EQ(p[0], mesh.nodes[i].x());
    EXPECT_EQ(p[1], mesh.nodes[i].y());
    EXPECT_EQ(p[2], 0.0);
  }
  for (int t = 0; t < mesh.num_cells(); ++t) {
    EXPECT_EQ(grid->GetCellType(t), VTK_TRIANGLE);
    vtkNew<vtkIdList> ids;
    grid->GetCellPoints(t, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(ids->GetId(k), mesh.cells[t][k]);
  }

  vtkDataArray* d = grid->GetPointData()->GetArray("displacement");
  ASSERT_NE(d, nullptr);
  ASSERT_EQ(d->GetNumberOfComponents(), 3);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(d->GetComponent(i, c), displacement[3 * i + c]);
  }
  auto* status = vtkIntArray::SafeDownCast(grid->GetPointData()->GetArray("contact_status"));
  ASSERT_NE(status, nullptr);
  EXPECT_EQ(status->GetValue(2), 0);
  EXPECT_EQ(status->GetValue(4), 1);

  vtkDataArray* vm = grid->GetCellData()->GetArray("von_mises");
  ASSERT_NE(vm, nullptr);
  EXPECT_EQ(vm->GetComponent(2, 0), 3.25);
  auto* sub = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("subdomain"));
  ASSERT_NE(sub, nullptr);
  EXPECT_EQ(sub->GetValue(0), 1);
  EXPECT_EQ(sub->GetValue(1), 2);

  // Texts are bytes (no string array: meshio cannot read those), numbers doubles.
  auto* title = vtkUnsignedCharArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("title"));
  ASSERT_NE(title, nullptr);
  std::string text;
  for (vtkIdType i = 0; i < title->GetNumberOfValues(); ++i)
    text += static_cast<char>(title->GetValue(i));
  EXPECT_EQ(text, "two-sub-domain rectangle, E = 2 GPa");
  vtkDataArray* factor = grid->GetFieldData()->GetArray("load_factor");
  ASSERT_NE(factor, nullptr);
  EXPECT_EQ(factor->GetTuple1(0), 0.25);

  // Only the target is left in the folder: the temporary file was renamed.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(VtkWriter, FieldOfTheWrongSizeIsRefusedAndNothingIsWritten) {
  const Mesh mesh = test::small_mesh();
  const fs::path path = dir_ / "bad.vtu";
  EXPECT_THROW(write_vtu(path, mesh, {{"displacement", 3, std::vector<double>(14, 0.0)}}, {}, {}),
               Error);
  EXPECT_THROW(write_vtu(path, mesh, {}, {{"von_mises", 1, {1.0, 2.0}}}, {}), Error);
  EXPECT_TRUE(fs::is_empty(dir_));
}

// A result that overflowed on its way out (no deck gives one now that its numbers and the
// displacements sig-post reads are bounded, core/ranges.hpp) is never written, naming the field.
TEST_F(VtkWriter, NonFiniteFieldIsRefusedAndNothingIsWritten) {
  const Mesh mesh = test::small_mesh();
  std::vector<double> stress(mesh.num_cells(), 1.0);
  stress.back() = std::numeric_limits<double>::infinity();
  try {
    write_vtu(dir_ / "inf.vtu", mesh, {}, {{"von_mises", 1, stress}}, {});
    ADD_FAILURE() << "an inf field was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("inf.vtu: field 'von_mises'"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(VtkWriter, UnwritableFolderIsAnError) {
  EXPECT_THROW(write_vtu(dir_ / "missing" / "x.vtu", test::small_mesh(), {}, {}, {}), Error);
}

TEST_F(VtkWriter, CollectionListsTheStepsInOrder) {
  const fs::path path = dir_ / "case.pvd";
  write_pvd(path, {{0.0, "case_0000.vtu"}, {0.25, "case_0001.vtu"}});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\"?>", 0), 0u);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
  const auto first = xml.find("timestep=\"0\" group=\"\" part=\"0\" file=\"case_0000.vtu\"");
  const auto second = xml.find("timestep=\"0.25\" group=\"\" part=\"0\" file=\"case_0001.vtu\"");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(first, second);
  EXPECT_NE(xml.find("</Collection>\n</VTKFile>"), std::string::npos);
}

} // namespace
} // namespace sig
