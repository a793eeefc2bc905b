#include "mesh/freefem.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"
#include "token_reader.hpp"

#include <cstdint>
#include <cstdlib>
#include <limits>

namespace sig {
namespace {

int node_index(TokenReader& in, int nv) {
  const long v = in.integer();
  if (v < 1 || v > nv)
    in.fail("vertex " + std::to_string(v) + " out of range 1.." + std::to_string(nv));
  return static_cast<int>(v - 1);
}

// A label is a reference by its absolute value, as NOPO keeps it.
int label(TokenReader& in) {
  const long value = in.integer();
  if (value < -std::numeric_limits<int>::max() || value > std::numeric_limits<int>::max())
    in.fail("label " + std::to_string(value) + " is out of range");
  return static_cast<int>(std::labs(value));
}

Mesh read_mesh(TokenReader& in) {
  // Counts checked against the file before anything is allocated: a vertex takes at least 6
  // bytes ("x y l\n"), a triangle 8, an edge 6.
  const long nv = in.count("vertices", 6), nt = in.count("triangles", 8),
             nbe = in.count("boundary edges", 6);
  if (nv < 3 || nt < 1) in.fail("bad header 'nv nt nbe': a mesh needs 3 vertices and a triangle");
  if (static_cast<std::uint64_t>(6 * nv + 8 * nt + 6 * nbe) > in.bytes_left() + 6)
    in.fail("the header announces " + std::to_string(nv) + " vertices, " + std::to_string(nt) +
            " triangles and " + std::to_string(nbe) + " edges, more than the " +
            std::to_string(in.bytes_left()) + " bytes left in the file hold");

  Mesh mesh;
  mesh.nodes.reserve(nv);
  for (long i = 0; i < nv; ++i) {
    const double x = in.real(), y = in.real();
    mesh.nodes.emplace_back(x, y);
    mesh.vertex_ref.push_back(label(in));
  }
  std::vector<int> triangle_lines;
  for (long t = 0; t < nt; ++t) {
    std::array<int, 3> tri{};
    for (int& v : tri)
      v = node_index(in, static_cast<int>(nv));
    const long region = in.integer();
    if (region < 0 || region > std::numeric_limits<int>::max())
      in.fail("region " + std::to_string(region) + " is out of range");
    mesh.cells.push_back(tri);
    mesh.subdomain.push_back(region > 0 ? static_cast<int>(region) : 1); // as NOPO stores it
    triangle_lines.push_back(in.line());
  }
  std::vector<int> edge_lines;
  for (long e = 0; e < nbe; ++e) {
    const int a = node_index(in, static_cast<int>(nv));
    const int b = node_index(in, static_cast<int>(nv));
    const int ref = label(in);
    if (ref == 0) continue; // no reference
    mesh.facets.push_back({{a, b}, ref});
    edge_lines.push_back(in.line());
  }
  if (!in.at_end()) {
    in.word();
    in.fail("unexpected data after the " + std::to_string(nbe) + " boundary edges");
  }

  orient_cells_of_file(mesh, in.file(), triangle_lines);
  if (const auto [first, second] = side_with_two_references(mesh); second >= 0)
    throw InputError(in.file(), edge_lines[second], "",
                     "the side from vertex " + std::to_string(mesh.facets[second].node[0] + 1) +
                         " to vertex " + std::to_string(mesh.facets[second].node[1] + 1) +
                         " carries labels " + std::to_string(mesh.facets[first].ref) + " (line " +
                         std::to_string(edge_lines[first]) + ") and " +
                         std::to_string(mesh.facets[second].ref) + ": a side carries one label");
  if (const int bad = orient_facets(mesh); bad >= 0)
    throw InputError(in.file(), edge_lines[bad], "",
                     "boundary edge with label " + std::to_string(mesh.facets[bad].ref) +
                         " is not a side of any triangle");
  check_mesh(mesh, in.file());
  return mesh;
}

} // namespace

Mesh read_freefem_msh(const std::filesystem::path& path) {
  TokenReader in(path);
  return read_mesh(in);
}

Mesh parse_freefem_msh(const std::string& name, std::string contents) {
  TokenReader in(name, std::move(contents));
  return read_mesh(in);
}

} // namespace sig
