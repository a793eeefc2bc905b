#include "post/dump.hpp"

#include "core/error.hpp"
#include "core/input_file.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <sstream>

namespace sig {
namespace {

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::string s;
  for (std::size_t i = 0; i < shape.size(); ++i)
    s += (i ? " x " : "") + std::to_string(shape[i]);
  return s;
}

std::string first_values(const Ds& ds, const DsArray& array, std::size_t max_values) {
  std::ostringstream out;
  out.precision(6);
  if (array.type == DsType::Text) {
    const std::string text = ds.text(array.name);
    const std::size_t width = 8 * max_values;
    out << '"' << text.substr(0, width) << (text.size() > width ? "...\"" : "\"");
    return out.str();
  }
  const std::size_t n = std::min(array.count(), max_values);
  if (array.type == DsType::Int64) {
    const auto v = ds.ints(array.name);
    for (std::size_t i = 0; i < n; ++i)
      out << (i ? " " : "") << v[i];
  } else {
    const auto v = ds.reals_any(array.name);
    for (std::size_t i = 0; i < n; ++i)
      out << (i ? " " : "") << v[i];
  }
  if (array.count() > n) out << " ...";
  return out.str();
}

Json array_values(const Ds& ds, const DsArray& array) {
  switch (array.type) {
  case DsType::Int64: {
    const auto v = ds.ints(array.name);
    return Json::array_of(std::vector<long long>(v.begin(), v.end()));
  }
  case DsType::Float64:
    return Json::array_of(ds.reals_any(array.name));
  case DsType::Text:
    return Json(ds.text(array.name));
  }
  return Json();
}

} // namespace

bool is_ds_file(const std::filesystem::path& path) {
  verify_regular_file(path, "file");
  std::ifstream in(path, std::ios::binary);
  SIG_VERIFY(in, path.string() << ": cannot open");
  std::array<char, 8> magic{};
  in.read(magic.data(), magic.size());
  return in.gcount() == 8 && std::memcmp(magic.data(), "SIGDS\0\0\0", 8) == 0;
}

std::string ds_type_name(DsType type) {
  switch (type) {
  case DsType::Int64:
    return "int64";
  case DsType::Float64:
    return "float64";
  case DsType::Text:
    return "text";
  }
  return "unknown";
}

std::string dump_ds_text(const Ds& ds, std::size_t max_values) {
  std::ostringstream out;
  const auto& h = ds.header;
  out << "DS " << h.kind << "  title: " << h.title << "\n"
      << "  date " << h.date << "  creator " << h.creator << "  level " << h.level << "  arrays "
      << ds.arrays().size() << "\n";
  std::size_t width = 4;
  for (const auto& a : ds.arrays())
    width = std::max(width, a.name.size());
  for (const auto& a : ds.arrays()) {
    std::string line = "  " + a.name + std::string(width - a.name.size() + 2, ' ');
    line += ds_type_name(a.type) + " [" + shape_text(a.shape) + "]  ";
    out << line << first_values(ds, a, max_values) << "\n";
  }
  return out.str();
}

Json dump_ds_json(const Ds& ds, const DumpValues& values) {
  for (const auto& name : values.names)
    SIG_VERIFY(ds.has(name),
               ds.source << ": no array '" << name << "' in this " << ds.header.kind << " DS");
  Json::Array arrays;
  for (const auto& a : ds.arrays()) {
    Json entry = Json::object();
    entry.set("name", a.name);
    entry.set("type", ds_type_name(a.type));
    entry.set("shape", Json::array_of(std::vector<long long>(a.shape.begin(), a.shape.end())));
    if (values.all || std::ranges::find(values.names, a.name) != values.names.end())
      entry.set("values", array_values(ds, a));
    arrays.push_back(std::move(entry));
  }
  Json j = Json::object();
  j.set("kind", ds.header.kind);
  j.set("title", ds.header.title);
  j.set("creator", ds.header.creator);
  j.set("date", ds.header.date);
  j.set("arrays", Json(std::move(arrays)));
  return j;
}

std::string dump_mesh_text(const Mesh& mesh, const std::string& title) {
  std::ostringstream out;
  const std::string cells = mesh.dim == 3 ? "tetrahedra" : "triangles";
  const std::string facets = mesh.dim == 3 ? "faces" : "edges";
  out << "NOPO mesh  title: " << title << "\n"
      << (mesh.dim == 3 ? "  3D" : "") << "  nodes " << mesh.num_nodes() << "  " << cells << " "
      << mesh.num_cells() << "  referenced " << facets << " " << mesh.facets.size() << "\n";
  out << "  references";
  for (int r : mesh.references()) {
    out << "  " << r << " (" << mesh.facets_with_ref(r).size() << " " << facets << ", "
        << mesh.nodes_with_ref(r).size() << " nodes)";
  }
  out << "\n  sub-domains";
  for (int s : mesh.subdomains()) {
    out << "  " << s << " (" << std::count(mesh.subdomain.begin(), mesh.subdomain.end(), s) << " "
        << cells << ")";
  }
  if (!mesh.nodes.empty()) {
    Point lo = mesh.nodes.front(), hi = mesh.nodes.front();
    for (const auto& p : mesh.nodes) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    out << "\n  bounding box";
    for (Eigen::Index k = 0; k < lo.size(); ++k)
      out << (k ? " x [" : " [") << lo[k] << ", " << hi[k] << "]";
  }
  out << "\n";
  return out.str();
}

Json dump_mesh_json(const Mesh& mesh, const std::string& title, bool with_values) {
  Json j = Json::object();
  j.set("kind", "NOPO");
  j.set("title", title);
  j.set("nodes", mesh.num_nodes());
  if (mesh.dim == 3) {
    // A 3D mesh says so, and names its cells and facets for what they are.
    j.set("dim", 3);
    j.set("tetrahedra", mesh.num_cells());
    j.set("boundary_faces", static_cast<long>(mesh.facets.size()));
  } else {
    j.set("triangles", mesh.num_cells());
    j.set("boundary_edges", static_cast<long>(mesh.facets.size()));
  }
  j.set("references", Json::array_of(mesh.references()));
  j.set("subdomains", Json::array_of(mesh.subdomains()));
  if (!with_values) return j;
  // The mesh itself, numbered from 1 as in the files.
  std::vector<double> xy;
  for (const Point& x : mesh.nodes)
    xy.insert(xy.end(), x.begin(), x.end());
  std::vector<long> cells, facets;
  for (const auto& c : mesh.cells)
    for (int v : c)
      cells.push_back(v + 1L);
  for (const Facet& f : mesh.facets) {
    for (int v : f.node)
      facets.push_back(v + 1L);
    facets.push_back(f.ref);
  }
  const std::string cell = mesh.dim == 3 ? "tetrahedron" : "triangle";
  j.set("coordinates", Json::array_of(xy));
  j.set(cell + "_nodes", Json::array_of(cells));
  j.set(cell + "_subdomain", Json::array_of(mesh.subdomain));
  j.set(mesh.dim == 3 ? "faces" : "edges", Json::array_of(facets));
  j.set("vertex_ref", Json::array_of(mesh.vertex_ref));
  return j;
}

} // namespace sig
