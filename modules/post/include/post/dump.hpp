#pragma once
// sig-dump: MODULEF's habit of printing a data structure, for any DS file or a NOPO mesh, as
// readable text or as JSON with stable keys for scripts.
#include "core/ds.hpp"
#include "core/json.hpp"
#include "mesh/mesh.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

/// True when the file starts with the DS magic "SIGDS\0\0\0" (NOPO files do not).
bool is_ds_file(const std::filesystem::path& path);

/// "int64", "float64" or "text".
std::string ds_type_name(DsType type);

/// Header lines, then one line per array: name, type, shape and its first `max_values` values.
std::string dump_ds_text(const Ds& ds, std::size_t max_values = 8);

/// The arrays whose values dump_ds_json prints: every one, or those named (each must exist).
struct DumpValues {
  bool all = false;
  std::vector<std::string> names;
};

/// {kind, title, creator, date, arrays: [{name, type, shape[, values]}]}: `values` for the arrays
/// `values` selects, a flat row-major list of numbers (non-finite ones null) or the text.
/// Throws naming the DS file when a selected array is missing.
Json dump_ds_json(const Ds& ds, const DumpValues& values = {});

/// Node, triangle and edge counts, references and sub-domains, bounding box.
std::string dump_mesh_text(const Mesh& mesh, const std::string& title);

/// {kind: "NOPO", title, nodes, triangles, boundary_edges, references, subdomains}; with
/// `with_values` the mesh too: coordinates (x, y per node), triangle_nodes (3 per triangle,
/// 1-based), triangle_subdomain, edges (a, b, ref per boundary edge, 1-based), vertex_ref.
Json dump_mesh_json(const Mesh& mesh, const std::string& title, bool with_values = false);

} // namespace sig
