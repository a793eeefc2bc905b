#include "post/vtk_writer.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/finite.hpp"
#include "core/phase_times.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <system_error>

namespace sig {
namespace {

vtkSmartPointer<vtkDataArray> make_array(const VtkField& field, long tuples,
                                         const std::string& where) {
  SIG_VERIFY(field.components >= 1,
             where << ": field '" << field.name << "' has " << field.components << " components");
  SIG_VERIFY(static_cast<long>(field.values.size()) == tuples * field.components,
             where << ": field '" << field.name << "' holds " << field.values.size()
                   << " values, expected " << tuples << " x " << field.components);
  const auto count = static_cast<vtkIdType>(field.values.size());
  if (field.integer) {
    auto array = vtkSmartPointer<vtkIntArray>::New();
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    array->SetNumberOfTuples(tuples);
    for (vtkIdType i = 0; i < count; ++i) {
      array->SetValue(i, static_cast<int>(std::lround(field.values[i])));
    }
    return array;
  }
  // A result that overflowed on its way here (stresses of a huge load) is never written.
  const std::string bad = first_non_finite(field.values);
  SIG_VERIFY(bad.empty(), where << ": field '" << field.name << "': " << bad
                                << ": a NaN or inf result is never written (check the loads "
                                   "and the units of the deck)");
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(field.name.c_str());
  array->SetNumberOfComponents(field.components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < count; ++i)
    array->SetValue(i, field.values[i]);
  return array;
}

vtkNew<vtkUnstructuredGrid> make_grid(const Mesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    points->SetPoint(i, mesh.nodes[i].x(), mesh.nodes[i].y(),
                     mesh.dim == 3 ? mesh.nodes[i].z() : 0.0);
  }
  const int vertices = mesh.dim + 1;
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(mesh.num_cells(), vertices * mesh.num_cells());
  for (const auto& cell : mesh.cells) {
    const vtkIdType ids[4] = {cell[0], cell[1], cell[2], cell[3]};
    cells->InsertNextCell(vertices, ids);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(mesh.dim == 3 ? VTK_TETRA : VTK_TRIANGLE, cells);
  return grid;
}

} // namespace

void write_vtu(const std::filesystem::path& path, const Mesh& mesh,
               const std::vector<VtkField>& point_fields, const std::vector<VtkField>& cell_fields,
               const VtkText& field_data, const VtkNumbers& field_numbers,
               VtkCompression compression) {
  const PhaseTimer timer("write");
  const std::string where = path.string();
  const auto folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  SIG_VERIFY(std::filesystem::is_directory(folder),
             where << ": folder " << folder.string() << " does not exist");
  auto grid = make_grid(mesh);
  for (const auto& field : point_fields) {
    grid->GetPointData()->AddArray(make_array(field, mesh.num_nodes(), where));
  }
  for (const auto& field : cell_fields) {
    grid->GetCellData()->AddArray(make_array(field, mesh.num_cells(), where));
  }
  for (const auto& [name, text] : field_data) {
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetName(name.c_str());
    bytes->SetNumberOfValues(static_cast<vtkIdType>(text.size()));
    for (std::size_t i = 0; i < text.size(); ++i)
      bytes->SetValue(static_cast<vtkIdType>(i), static_cast<unsigned char>(text[i]));
    grid->GetFieldData()->AddArray(bytes);
  }
  for (const auto& [name, value] : field_numbers) {
    vtkNew<vtkDoubleArray> number;
    number->SetName(name.c_str());
    number->InsertNextValue(value);
    grid->GetFieldData()->AddArray(number);
  }

  // The name every atomic write uses: a killed sig-post's leftover is found at the next start.
  const auto tmp = temporary_path(path);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(tmp.string().c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff(); // raw binary: smaller and faster than base64
  switch (compression) {
  case VtkCompression::lz4:
    writer->SetCompressorTypeToLZ4();
    break;
  case VtkCompression::zlib:
    writer->SetCompressorTypeToZLib();
    // zlib's fastest level: a .vtu of 1.5M triangles is written several times faster than at
    // VTK's default (5), a few per cent larger.
    writer->SetCompressionLevel(1);
    break;
  case VtkCompression::none:
    writer->SetCompressorTypeToNone();
    break;
  }
  const int ok = writer->Write();
  if (ok != 1 || writer->GetErrorCode() != 0) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw Error(where + ": VTK could not write the file (error code " +
                std::to_string(writer->GetErrorCode()) + ")");
  }
  stop_point_for_tests(path);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  SIG_VERIFY(!ec, where << ": cannot rename " << tmp.string() << ": " << ec.message());
}

void write_pvd(const std::filesystem::path& path, const std::vector<PvdStep>& steps) {
  std::ostringstream xml;
  xml.precision(17);
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (const auto& step : steps) {
    SIG_VERIFY(std::isfinite(step.time),
               path.string() << ": step '" << step.file << "' has a non-finite time");
    SIG_VERIFY(step.file.find_first_of("\"<>&") == std::string::npos,
               path.string() << ": file name '" << step.file << "' needs XML escaping");
    xml << "    <DataSet timestep=\"" << step.time << "\" group=\"\" part=\"0\" file=\""
        << step.file << "\"/>\n";
  }
  xml << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(path, xml.str());
}

std::vector<std::filesystem::path>
write_vtu_series(const std::filesystem::path& outdir, const std::string& stem, const Mesh& mesh,
                 std::size_t count, const std::function<VtkState(std::size_t)>& state,
                 VtkCompression compression) {
  std::vector<std::filesystem::path> files{outdir / (stem + ".pvd")};
  std::vector<PvdStep> steps;
  for (std::size_t s = 0; s < count; ++s) {
    VtkState fields = state(s);
    fields.field_numbers.emplace_back("TimeValue", fields.time);
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%04zu.vtu", s);
    const std::string vtu = stem + suffix;
    write_vtu(outdir / vtu, mesh, fields.point, fields.cell, fields.field_data,
              fields.field_numbers, compression);
    steps.push_back({fields.time, vtu});
    files.push_back(outdir / vtu);
  }
  write_pvd(files.front(), steps);
  return files;
}

} // namespace sig
