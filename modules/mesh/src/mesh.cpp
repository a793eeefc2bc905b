#include "mesh/mesh.hpp"

#include "core/error.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace sig {
namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

std::vector<int> Mesh::nodes_with_ref(int ref) const {
  std::vector<int> result;
  for (const auto& e : edges) {
    if (e.ref == ref) {
      result.push_back(e.a);
      result.push_back(e.b);
    }
  }
  for (std::size_t i = 0; i < vertex_ref.size(); ++i) {
    if (vertex_ref[i] == ref) result.push_back(static_cast<int>(i));
  }
  sort_unique(result);
  return result;
}

std::vector<BoundaryEdge> Mesh::edges_with_ref(int ref) const {
  std::vector<BoundaryEdge> result;
  std::copy_if(edges.begin(), edges.end(), std::back_inserter(result),
               [ref](const BoundaryEdge& e) { return e.ref == ref; });
  return result;
}

std::vector<int> Mesh::references() const {
  std::vector<int> result;
  for (const auto& e : edges)
    result.push_back(e.ref);
  for (int r : vertex_ref) {
    if (r != 0) result.push_back(r);
  }
  sort_unique(result);
  return result;
}

std::vector<int> Mesh::subdomains() const {
  std::vector<int> result = subdomain;
  sort_unique(result);
  return result;
}

double signed_double_area(const Mesh& mesh, int t) {
  const auto& tri = mesh.triangles[t];
  const Eigen::Vector2d u = mesh.nodes[tri[1]] - mesh.nodes[tri[0]];
  const Eigen::Vector2d v = mesh.nodes[tri[2]] - mesh.nodes[tri[0]];
  return u.x() * v.y() - u.y() * v.x();
}

void check_mesh(const Mesh& mesh, const std::string& source) {
  const int nn = mesh.num_nodes();
  const int nt = mesh.num_triangles();
  SIG_VERIFY(nt > 0, source << ": the mesh has no triangle");
  SIG_VERIFY(mesh.subdomain.size() == mesh.triangles.size(), source << ": " << mesh.subdomain.size()
                                                                    << " sub-domain numbers for "
                                                                    << nt << " triangles");
  SIG_VERIFY(mesh.vertex_ref.size() == mesh.nodes.size(), source << ": " << mesh.vertex_ref.size()
                                                                 << " vertex references for " << nn
                                                                 << " nodes");
  for (int i = 0; i < nn; ++i) {
    SIG_VERIFY(mesh.nodes[i].allFinite(),
               source << ": node " << i + 1 << " (1-based) has a non-finite coordinate");
    SIG_VERIFY(mesh.vertex_ref[i] >= 0, source << ": node " << i + 1
                                               << " (1-based) has a negative reference "
                                               << mesh.vertex_ref[i]);
  }
  std::vector<char> used(nn, 0);
  for (int t = 0; t < nt; ++t) {
    for (int v : mesh.triangles[t]) {
      SIG_VERIFY(v >= 0 && v < nn, source << ": triangle " << t + 1 << " (1-based) uses node "
                                          << v + 1 << ", out of range 1.." << nn);
      used[v] = 1;
    }
    SIG_VERIFY(mesh.subdomain[t] >= 1, source << ": triangle " << t + 1
                                              << " (1-based) has sub-domain " << mesh.subdomain[t]
                                              << " (must be >= 1)");
    const double area = 0.5 * signed_double_area(mesh, t);
    SIG_VERIFY(area > 0, source << ": triangle " << t + 1
                                << " (1-based) is inverted or degenerate (signed area " << area
                                << ")");
  }
  for (int i = 0; i < nn; ++i) {
    SIG_VERIFY(used[i], source << ": node " << i + 1 << " (1-based) is used by no triangle");
  }
  std::unordered_set<std::uint64_t> sides;
  for (const auto& tri : mesh.triangles) {
    for (int j = 0; j < 3; ++j)
      sides.insert(edge_key(tri[j], tri[(j + 1) % 3]));
  }
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const BoundaryEdge& edge = mesh.edges[e];
    SIG_VERIFY(edge.a >= 0 && edge.a < nn && edge.b >= 0 && edge.b < nn,
               source << ": edge " << e + 1 << " (1-based) uses a node out of range 1.." << nn);
    SIG_VERIFY(edge.ref >= 1, source << ": edge " << e + 1 << " (1-based) has reference "
                                     << edge.ref << " (must be >= 1)");
    SIG_VERIFY(sides.count(edge_key(edge.a, edge.b)),
               source << ": edge " << e + 1 << " (1-based) from node " << edge.a + 1 << " to node "
                      << edge.b + 1 << " is not a side of any triangle");
  }
}

} // namespace sig
