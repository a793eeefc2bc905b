#pragma once
// ParaView output: one .vtu per output time (the mesh with its point, cell and field data) and a
// .pvd collection listing them with their times. Both are written atomically (temporary file in
// the same folder, then renamed), so ParaView never opens a half-written step. Every array has a
// numeric type, so that ParaView, VTK's readers, pyvista and meshio all read the files (meshio
// stops at VTK's string arrays).
#include "mesh/mesh.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sig {

/// A data array attached to the points or the cells of the mesh: `values` holds
/// `components` numbers per point (or cell), interleaved.
struct VtkField {
  std::string name;
  int components = 1;
  std::vector<double> values;
  bool integer = false; ///< written as vtkIntArray (sub-domains, statuses)
};

/// Field data of the whole grid: named texts (title, method ...), each stored as its UTF-8 bytes in
/// an unsigned char array (XML type UInt8; Python: bytes(array).decode()).
using VtkText = std::vector<std::pair<std::string, std::string>>;
/// Field data of the whole grid: named numbers (load_step, load_factor ...), Float64.
using VtkNumbers = std::vector<std::pair<std::string, double>>;

/// How the .vtu's binary arrays are compressed (OUTPUT compression=). zlib (level 1) is read by
/// every VTK XML reader, meshio included; LZ4 writes the 1.5M-node Hertz mesh in about half
/// zlib's time, the file a fifth larger, and is read by ParaView and VTK (8.1 on) but not by
/// meshio 5.0 (Debian 12's); none is the largest.
enum class VtkCompression { lz4, zlib, none };

/// Write the mesh (z = 0) with its fields as a binary .vtu. Throws sig::Error when a field does
/// not have one tuple per point (cell) or the file cannot be written.
void write_vtu(const std::filesystem::path& path, const Mesh& mesh,
               const std::vector<VtkField>& point_fields, const std::vector<VtkField>& cell_fields,
               const VtkText& field_data, const VtkNumbers& field_numbers = {},
               VtkCompression compression = VtkCompression::zlib);

struct PvdStep {
  double time = 0;
  std::string file; ///< .vtu name relative to the .pvd's folder
};

/// Write a ParaView collection listing the steps in order.
void write_pvd(const std::filesystem::path& path, const std::vector<PvdStep>& steps);

/// One state of a series: its (pseudo-)time and what write_vtu writes for it.
struct VtkState {
  double time = 0;
  std::vector<VtkField> point;
  std::vector<VtkField> cell;
  VtkText field_data;
  VtkNumbers field_numbers;
};

/// A series for ParaView: OUTDIR/<stem>_NNNN.vtu for state NNNN = 0 .. count-1 (made one at a
/// time by `state`, so a long series never sits in memory whole) and OUTDIR/<stem>.pvd listing
/// them with their times; each .vtu also holds its time as the field data TimeValue (ParaView's
/// name for it, so a .vtu opened alone knows its time). Returns the .pvd, then the .vtu files.
std::vector<std::filesystem::path>
write_vtu_series(const std::filesystem::path& outdir, const std::string& stem, const Mesh& mesh,
                 std::size_t count, const std::function<VtkState(std::size_t)>& state,
                 VtkCompression compression = VtkCompression::zlib);

} // namespace sig
