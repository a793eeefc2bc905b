#include "mesh/topology.hpp"

#include "core/error.hpp"
#include "core/log.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace sig {

int orient_counter_clockwise(Mesh& mesh, std::vector<int>* flipped) {
  int degenerate = -1;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const double area = signed_double_area(mesh, t);
    if (area < 0) {
      std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
      if (flipped != nullptr) flipped->push_back(t);
    }
    if (area == 0 && degenerate < 0) degenerate = t;
  }
  return degenerate;
}

void orient_triangles_of_file(Mesh& mesh, const std::string& file, const std::vector<int>& lines) {
  std::vector<int> flipped;
  if (const int flat = orient_counter_clockwise(mesh, &flipped); flat >= 0)
    throw InputError(file, lines[flat], "",
                     "triangle " + std::to_string(flat + 1) +
                         " (1-based) is degenerate: its three nodes are aligned (zero area)");
  if (const TriangleOverlap overlap = find_overlap(mesh); overlap.second >= 0)
    throw InputError(file, lines[overlap.second], "", overlap.what);
  std::vector<long> numbers;
  for (int t : flipped)
    numbers.push_back(t + 1);
  warn_entities(file, "clockwise triangle(s) (1-based, in file order)", numbers, "reoriented");
}

TriangleOverlap find_overlap(const Mesh& mesh) {
  // Counter-clockwise triangles that tile a domain run through each interior side once in each
  // direction: a directed side met twice belongs to two triangles on the same side of it.
  std::unordered_map<std::uint64_t, int> directed; // (from, to) -> triangle
  directed.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t from = tri[j], to = tri[(j + 1) % 3];
      const auto [it, fresh] = directed.try_emplace((from << 32) | to, t);
      if (fresh) continue;
      const int other = it->second;
      std::array<int, 3> a = mesh.triangles[other], b = tri;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      const std::string pair = "triangles " + std::to_string(other + 1) + " and " +
                               std::to_string(t + 1) + " (1-based) ";
      if (a == b)
        return {other, t,
                pair + "are one triangle listed twice (nodes " + std::to_string(a[0] + 1) + ", " +
                    std::to_string(a[1] + 1) + ", " + std::to_string(a[2] + 1) +
                    "): the body would count twice there"};
      return {other, t,
              pair + "overlap: both lie on the same side of their common side from node " +
                  std::to_string(from + 1) + " to node " + std::to_string(to + 1)};
    }
  }
  return {};
}

std::pair<int, int> side_with_two_references(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, int> first; // side -> first edge on it
  for (int e = 0; e < static_cast<int>(mesh.edges.size()); ++e) {
    const BoundaryEdge& edge = mesh.edges[e];
    const auto [it, fresh] = first.try_emplace(edge_key(edge.a, edge.b), e);
    if (!fresh && mesh.edges[it->second].ref != edge.ref) return {it->second, e};
  }
  return {-1, -1};
}

int orient_boundary_edges(Mesh& mesh) {
  struct Side {
    int from, to, count;
  };
  std::unordered_map<std::uint64_t, Side> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (const auto& tri : mesh.triangles) {
    for (int j = 0; j < 3; ++j) {
      const int a = tri[j], b = tri[(j + 1) % 3];
      auto [it, fresh] = sides.try_emplace(edge_key(a, b), Side{a, b, 0});
      ++it->second.count;
    }
  }
  std::vector<BoundaryEdge> kept;
  kept.reserve(mesh.edges.size());
  std::unordered_set<std::uint64_t> seen;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    BoundaryEdge edge = mesh.edges[e];
    const auto it = sides.find(edge_key(edge.a, edge.b));
    if (it == sides.end()) return static_cast<int>(e);
    if (!seen.insert(it->first).second) continue;
    if (it->second.count == 1) {
      edge.a = it->second.from;
      edge.b = it->second.to;
    }
    kept.push_back(edge);
  }
  mesh.edges = std::move(kept);
  return -1;
}

std::vector<int> drop_unused_nodes(Mesh& mesh) {
  std::vector<int> renumber(mesh.nodes.size(), -1);
  for (const auto& tri : mesh.triangles) {
    for (int v : tri)
      renumber[v] = 0;
  }
  int next = 0;
  for (std::size_t i = 0; i < renumber.size(); ++i) {
    if (renumber[i] < 0) continue;
    renumber[i] = next;
    mesh.nodes[next] = mesh.nodes[i];
    if (i < mesh.vertex_ref.size()) mesh.vertex_ref[next] = mesh.vertex_ref[i];
    ++next;
  }
  mesh.nodes.resize(next);
  if (!mesh.vertex_ref.empty()) mesh.vertex_ref.resize(next);
  for (auto& tri : mesh.triangles) {
    for (int& v : tri)
      v = renumber[v];
  }
  for (auto& edge : mesh.edges) {
    edge.a = renumber[edge.a];
    edge.b = renumber[edge.b];
  }
  return renumber;
}

std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh) {
  std::vector<std::pair<int, int>> pairs;
  if (mesh.nodes.empty()) return pairs;
  Eigen::Vector2d low = mesh.nodes.front(), high = low;
  for (const Eigen::Vector2d& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  const double tolerance = 1e-10 * (high - low).norm();
  // Sweep along x1: only nodes within the tolerance in x1 can coincide.
  std::vector<int> order(mesh.nodes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return mesh.nodes[a].x() < mesh.nodes[b].x(); });
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1;
         j < order.size() && mesh.nodes[order[j]].x() - mesh.nodes[order[i]].x() <= tolerance; ++j)
      if ((mesh.nodes[order[j]] - mesh.nodes[order[i]]).norm() <= tolerance)
        pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

void warn_entities(const std::string& file, const std::string& what,
                   const std::vector<long>& numbers, const std::string& action) {
  if (numbers.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < numbers.size() && k < 10; ++k)
    list += (k ? ", " : "") + std::to_string(numbers[k]);
  if (numbers.size() > 10) list += ", ...";
  log_warning(file + ": " + action + " " + std::to_string(numbers.size()) + " " + what + ": " +
              list);
}

} // namespace sig
