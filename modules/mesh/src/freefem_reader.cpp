#include "mesh/freefem.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"
#include "token_reader.hpp"

#include <cstdlib>

namespace sig {
namespace {

int node_index(TokenReader& in, int nv) {
  const long v = in.integer();
  if (v < 1 || v > nv)
    in.fail("vertex " + std::to_string(v) + " out of range 1.." + std::to_string(nv));
  return static_cast<int>(v - 1);
}

} // namespace

Mesh read_freefem_msh(const std::filesystem::path& path) {
  TokenReader in(path);
  const long nv = in.integer(), nt = in.integer(), nbe = in.integer();
  if (nv < 3 || nt < 1 || nbe < 0) in.fail("bad header 'nv nt nbe'");

  Mesh mesh;
  mesh.nodes.reserve(nv);
  for (long i = 0; i < nv; ++i) {
    const double x = in.real(), y = in.real();
    mesh.nodes.emplace_back(x, y);
    mesh.vertex_ref.push_back(static_cast<int>(std::labs(in.integer())));
  }
  std::vector<int> triangle_lines;
  for (long t = 0; t < nt; ++t) {
    std::array<int, 3> tri{};
    for (int& v : tri)
      v = node_index(in, static_cast<int>(nv));
    const long region = in.integer();
    if (region < 0) in.fail("negative region " + std::to_string(region));
    mesh.triangles.push_back(tri);
    mesh.subdomain.push_back(region > 0 ? static_cast<int>(region) : 1); // as NOPO stores it
    triangle_lines.push_back(in.line());
  }
  std::vector<int> edge_lines;
  for (long e = 0; e < nbe; ++e) {
    const int a = node_index(in, static_cast<int>(nv));
    const int b = node_index(in, static_cast<int>(nv));
    const long label = std::labs(in.integer());
    if (label == 0) continue; // no reference
    mesh.edges.push_back({a, b, static_cast<int>(label)});
    edge_lines.push_back(in.line());
  }
  if (!in.at_end()) {
    in.word();
    in.fail("unexpected data after the " + std::to_string(nbe) + " boundary edges");
  }

  if (const int flat = orient_counter_clockwise(mesh); flat >= 0)
    throw InputError(in.file(), triangle_lines[flat], "",
                     "triangle " + std::to_string(flat + 1) +
                         " (1-based) is degenerate: its three nodes are aligned (zero area)");
  if (const int bad = orient_boundary_edges(mesh); bad >= 0)
    throw InputError(in.file(), edge_lines[bad], "",
                     "boundary edge with label " + std::to_string(mesh.edges[bad].ref) +
                         " is not a side of any triangle");
  check_mesh(mesh, in.file());
  return mesh;
}

} // namespace sig
