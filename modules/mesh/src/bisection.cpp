// Longest-edge bisection (mesh/bisection.hpp): the closure of the marked edges over the edge ->
// triangles adjacency, then each triangle cut recursively along its marked edges.
#include "mesh/bisection.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>

namespace sig {
namespace {

/// The local index k of triangle t's refinement edge (v[k], v[k+1]): its longest, ties broken
/// by the edge's node numbers so that the choice depends on the triangle alone.
int refinement_edge(const Mesh& mesh, int t) {
  const auto& v = mesh.cells[t];
  int best = 0;
  double best_length = -1;
  std::uint64_t best_key = 0;
  for (int k = 0; k < 3; ++k) {
    const int a = v[k], b = v[(k + 1) % 3];
    const double length = (mesh.nodes[a] - mesh.nodes[b]).squaredNorm();
    const std::uint64_t key = edge_key(a, b);
    if (length > best_length || (length == best_length && key < best_key)) {
      best = k;
      best_length = length;
      best_key = key;
    }
  }
  return best;
}

/// The edges to bisect: the marked triangles' three edges, closed so that every triangle with a
/// bisected edge has its refinement edge bisected. The value is the new node (set later).
std::unordered_map<std::uint64_t, int> closed_edges(const Mesh& mesh,
                                                    const std::vector<int>& marked) {
  std::unordered_map<std::uint64_t, std::array<int, 2>> triangles_of; // -1: none
  std::vector<std::uint64_t> refinement(mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto& v = mesh.cells[t];
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] =
          triangles_of.try_emplace(edge_key(v[k], v[(k + 1) % 3]), std::array<int, 2>{t, -1});
      if (!fresh) it->second[1] = t;
    }
    const int k = refinement_edge(mesh, t);
    refinement[t] = edge_key(v[k], v[(k + 1) % 3]);
  }
  std::unordered_map<std::uint64_t, int> bisected;
  std::vector<std::uint64_t> work;
  const auto bisect_edge = [&](std::uint64_t key) {
    if (bisected.try_emplace(key, -1).second) work.push_back(key);
  };
  for (int t : marked) {
    SIG_VERIFY(t >= 0 && t < mesh.num_cells(),
               "bisect: marked triangle " << t << " of " << mesh.num_cells());
    const auto& v = mesh.cells[t];
    for (int k = 0; k < 3; ++k)
      bisect_edge(edge_key(v[k], v[(k + 1) % 3]));
  }
  while (!work.empty()) {
    const std::uint64_t key = work.back();
    work.pop_back();
    for (int t : triangles_of.at(key))
      if (t >= 0) bisect_edge(refinement[t]);
  }
  return bisected;
}

/// Cut (a, b, c), counter-clockwise with refinement edge (a, b), along its bisected edges: the
/// children (c, a, m) and (b, c, m) have the old edges (c, a) and (b, c) as refinement edges,
/// and their new edges are never bisected in this pass: 2, 3 or 4 triangles.
void cut(int a, int b, int c, int subdomain, const std::unordered_map<std::uint64_t, int>& bisected,
         Mesh& out) {
  const auto found = bisected.find(edge_key(a, b));
  if (found == bisected.end()) {
    out.cells.push_back(Simplex{a, b, c});
    out.subdomain.push_back(subdomain);
    return;
  }
  const int m = found->second;
  cut(c, a, m, subdomain, bisected, out);
  cut(b, c, m, subdomain, bisected, out);
}

} // namespace

Bisection bisect(const Mesh& mesh, const std::vector<int>& marked,
                 const std::vector<BoundaryArc>& arcs, double max_nodes) {
  SIG_VERIFY(mesh.dim == 2,
             "bisect: refinement of a " << mesh.dim << "D mesh is not implemented (2D only)");
  std::unordered_map<std::uint64_t, int> bisected = closed_edges(mesh, marked);
  const double nodes = static_cast<double>(mesh.num_nodes()) + static_cast<double>(bisected.size());
  SIG_VERIFY(nodes <= max_nodes, "bisect: the refined mesh would have "
                                     << nodes << " nodes (" << mesh.num_nodes() << " + "
                                     << bisected.size() << " bisected edges), beyond the limit of "
                                     << max_nodes << " (mesh/mesh.hpp max_mesh_nodes)");
  Bisection result;
  Mesh& out = result.mesh;
  out.nodes = mesh.nodes;
  out.vertex_ref = mesh.vertex_ref;
  // The new nodes in the order of the edges' keys, so that the numbering does not depend on
  // the hash table's.
  std::vector<std::uint64_t> keys;
  keys.reserve(bisected.size());
  for (const auto& [key, node] : bisected)
    keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  std::unordered_map<std::uint64_t, int> ref_of;
  for (const Facet& e : mesh.facets)
    ref_of[edge_key(e.node[0], e.node[1])] = e.ref;
  for (std::uint64_t key : keys) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    Eigen::Vector2d x = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
    if (const auto r = ref_of.find(key); r != ref_of.end()) x = onto_boundary(arcs, r->second, x);
    bisected[key] = out.num_nodes();
    out.nodes.push_back(x);
    out.vertex_ref.push_back(0);
  }
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto& v = mesh.cells[t];
    const int k = refinement_edge(mesh, t);
    cut(v[k], v[(k + 1) % 3], v[(k + 2) % 3], mesh.subdomain[t], bisected, out);
  }
  for (const Facet& e : mesh.facets) {
    const auto found = bisected.find(edge_key(e.node[0], e.node[1]));
    if (found == bisected.end()) {
      out.facets.push_back(e);
      continue;
    }
    out.facets.push_back({Simplex{e.node[0], found->second}, e.ref});
    out.facets.push_back({Simplex{found->second, e.node[1]}, e.ref});
  }
  result.bisected_edges = static_cast<int>(keys.size());
  check_mesh(out, "bisect");
  return result;
}

} // namespace sig
