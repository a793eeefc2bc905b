#include "mesh/mesh.hpp"

#include "core/error.hpp"
#include "core/ranges.hpp"
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

double diameter(const Mesh& mesh) {
  if (mesh.nodes.empty()) return 0;
  Eigen::Vector2d low = mesh.nodes.front(), high = low;
  for (const Eigen::Vector2d& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  return (high - low).norm();
}

namespace {

// A P1 stiffness of a triangle whose longest side is A times its height has a condition number
// of about A^2: beyond 1e6 it keeps fewer than 4 digits.
constexpr double kMaxAspectRatio = 1e6;

// The mesh's size and its triangles' shapes within what a solve can carry (core/ranges.hpp: the
// magnitudes of the deck's lengths).
void verify_scale(const Mesh& mesh, const std::string& source) {
  for (const Eigen::Vector2d& x : mesh.nodes)
    for (const double c : {x.x(), x.y()})
      SIG_VERIFY(std::abs(c) <= kLargestMagnitude, source << ": a node at (" << x.x() << ", "
                                                          << x.y() << "): " << magnitude_excess(c));
  const double size = diameter(mesh);
  SIG_VERIFY(magnitude_excess(size).empty(),
             source << ": the mesh spans " << size
                    << " (the diagonal of its bounding box): " << magnitude_excess(size));
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    double longest = 0;
    for (int j = 0; j < 3; ++j)
      longest = std::max(longest, (mesh.nodes[tri[(j + 1) % 3]] - mesh.nodes[tri[j]]).norm());
    const double height = signed_double_area(mesh, t) / longest;
    SIG_VERIFY(longest <= kMaxAspectRatio * height,
               source << ": triangle " << t + 1 << " (1-based) is flat: its longest side, "
                      << longest << ", is " << longest / height << " times its height, more than "
                      << kMaxAspectRatio << " (a P1 stiffness of it would keep no digits)");
  }
}

} // namespace

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
  verify_scale(mesh, source);
  if (const TriangleOverlap overlap = find_overlap(mesh); overlap.second >= 0)
    SIG_VERIFY(false, source << ": " << overlap.what);
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
