#include "mesh/topology.hpp"

#include "core/error.hpp"
#include "core/log.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace sig {

FacetKey facet_key(const Simplex& facet) {
  FacetKey key{-1, -1, -1};
  std::copy(facet.begin(), facet.end(), key.begin());
  // Sorting two or three words by exchanges (std::sort on a part of the array trips GCC's
  // -Warray-bounds).
  if (key[0] > key[1]) std::swap(key[0], key[1]);
  if (facet.size() == 3) {
    if (key[1] > key[2]) std::swap(key[1], key[2]);
    if (key[0] > key[1]) std::swap(key[0], key[1]);
  }
  return key;
}

// The local numbering of a tetrahedron's faces is MODULEF's (its user guide's reference
// tetrahedron: face 1 = vertices 1 3 2, face 2 = 1 4 3, face 3 = 1 2 4, face 4 = 2 3 4; edges
// 1-2, 2-3, 3-1, 1-4, 2-4, 3-4), so that the face references of a NOPO element (INING = 1)
// are read and written in the order MODULEF's own modules expect. Each face so listed turns
// counter-clockwise seen from outside a positively oriented tetrahedron (det[x1-x0, x2-x0,
// x3-x0] > 0): its right-hand normal points out, as a traction's normal must. MODULEF.md has
// verified the triangle's numbering on files; the tetrahedron's follows the guides and has not
// been checked against a MODULEF file.
OutwardFacets outward_facet_array(const Simplex& cell) {
  if (cell.size() == 3)
    return {{Simplex{cell[0], cell[1]}, Simplex{cell[1], cell[2]}, Simplex{cell[2], cell[0]}}, 3};
  return {{Simplex{cell[0], cell[2], cell[1]}, Simplex{cell[0], cell[3], cell[2]},
           Simplex{cell[0], cell[1], cell[3]}, Simplex{cell[1], cell[2], cell[3]}},
          4};
}

std::vector<Simplex> outward_facets(const Simplex& cell) {
  const OutwardFacets facets = outward_facet_array(cell);
  return {facets.begin(), facets.end()};
}

std::vector<char> nodes_on_facets(const Mesh& mesh) {
  std::vector<char> on(mesh.nodes.size(), 0);
  for (const Facet& f : mesh.facets)
    for (int v : f.node)
      if (v >= 0 && static_cast<std::size_t>(v) < on.size()) on[v] = 1;
  return on;
}

bool all_marked(const std::vector<char>& marks, const Simplex& f) {
  for (int v : f)
    if (v < 0 || static_cast<std::size_t>(v) >= marks.size() || !marks[v]) return false;
  return true;
}

int orient_cells(Mesh& mesh, std::vector<int>* flipped) {
  int degenerate = -1;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const double measure = signed_cell_determinant(mesh, t);
    if (measure < 0) {
      // Swapping the last two nodes reverses the orientation of a triangle and a tetrahedron.
      std::swap(mesh.cells[t][mesh.dim - 1], mesh.cells[t][mesh.dim]);
      if (flipped != nullptr) flipped->push_back(t);
    }
    if (measure == 0 && degenerate < 0) degenerate = t;
  }
  return degenerate;
}

void orient_cells_of_file(Mesh& mesh, const std::string& file, const std::vector<int>& lines) {
  std::vector<int> flipped;
  if (const int flat = orient_cells(mesh, &flipped); flat >= 0)
    throw InputError(file, lines[flat], "",
                     mesh.dim == 2 ? "triangle " + std::to_string(flat + 1) +
                                         " (1-based) is degenerate: its three nodes are aligned "
                                         "(zero area)"
                                   : "tetrahedron " + std::to_string(flat + 1) +
                                         " (1-based) is degenerate: its four nodes are in one "
                                         "plane (zero volume)");
  if (const CellOverlap overlap = find_overlap(mesh); overlap.second >= 0)
    throw InputError(file, lines[overlap.second], "", overlap.what);
  std::vector<long> numbers;
  for (int t : flipped)
    numbers.push_back(t + 1);
  warn_entities(file,
                mesh.dim == 2 ? "clockwise triangle(s) (1-based, in file order)"
                              : "left-handed tetrahedra (1-based, in file order)",
                numbers, "reoriented");
}

namespace {

/// A facet with its orientation: an edge as it is (from, to); a triangle with its nodes rotated
/// so that the smallest comes first (a rotation keeps the triangle's orientation, the opposite
/// face differs).
FacetKey directed_key(const Simplex& f) {
  FacetKey key{-1, -1, -1};
  const int n = f.size();
  if (n == 2) return {f[0], f[1], -1};
  const int first = static_cast<int>(std::min_element(f.begin(), f.end()) - f.begin());
  for (int j = 0; j < n; ++j)
    key[j] = f[(first + j) % n];
  return key;
}

/// The nodes in increasing order, by insertion (std::sort on a Simplex trips GCC's
/// -Warray-bounds: it cannot see that size() <= 4).
Simplex sorted(Simplex nodes) {
  for (int i = 1; i < nodes.size(); ++i)
    for (int j = i; j > 0 && nodes[j - 1] > nodes[j]; --j)
      std::swap(nodes[j - 1], nodes[j]);
  return nodes;
}

std::string node_list(Simplex nodes) {
  nodes = sorted(nodes);
  std::string list;
  for (int v : nodes)
    list += (list.empty() ? "" : ", ") + std::to_string(v + 1);
  return list;
}

} // namespace

CellOverlap find_overlap(const Mesh& mesh) {
  // Positively oriented cells that tile a domain run through each interior facet once in each
  // orientation: an oriented facet met twice belongs to two cells on the same side of it. The
  // oriented facets are bucketed by their first node (a counting sort, no hash table: a mesh of
  // millions of cells is checked in a fraction of a second); the overlap reported is the one a
  // scan of the cells in order meets first: the earliest second occurrence of an oriented facet,
  // with the cell of its first.
  const int per = mesh.dim + 1;
  const auto facets = static_cast<std::int64_t>(per) * mesh.num_cells();
  int top = -1;
  for (const Simplex& cell : mesh.cells)
    for (int v : cell) {
      SIG_VERIFY(v >= 0, "find_overlap: negative node index " << v);
      top = std::max(top, v);
    }
  std::vector<std::int64_t> start(static_cast<std::size_t>(top) + 2, 0);
  for (const Simplex& cell : mesh.cells)
    for (const Simplex& f : outward_facet_array(cell))
      ++start[directed_key(f)[0] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  struct Entry {
    int second, third;     // the oriented facet's other two key words
    std::int64_t position; // cell * per + local facet: the scan order
  };
  std::vector<Entry> entries(static_cast<std::size_t>(facets));
  {
    std::vector<std::int64_t> next(start.begin(), start.end() - 1);
    std::int64_t position = 0;
    for (const Simplex& cell : mesh.cells)
      for (const Simplex& f : outward_facet_array(cell)) {
        const FacetKey key = directed_key(f);
        entries[next[key[0]]++] = {key[1], key[2], position++};
      }
  }
  std::int64_t first = -1, second = -1; // positions of the overlap met first
  for (std::size_t b = 0; b + 1 < start.size(); ++b) {
    const auto begin = entries.begin() + start[b], end = entries.begin() + start[b + 1];
    if (end - begin < 2) continue;
    // Within a bucket the entries are in scan order; sorted by key, then position, a repeated
    // oriented facet's first two occurrences are neighbours.
    // Insertion sort for the usual bucket: the few facets around one node.
    const auto less = [](const Entry& a, const Entry& c) {
      return std::tie(a.second, a.third, a.position) < std::tie(c.second, c.third, c.position);
    };
    if (end - begin > 16) {
      std::sort(begin, end, less);
    } else {
      for (auto i = begin + 1; i != end; ++i)
        for (auto j = i; j != begin && less(*j, *(j - 1)); --j)
          std::iter_swap(j, j - 1);
    }
    for (auto it = begin; it + 1 != end; ++it) {
      const auto next = it + 1;
      if (next->second != it->second || next->third != it->third) continue;
      if (it != begin && (it - 1)->second == it->second && (it - 1)->third == it->third) continue;
      if (second < 0 || next->position < second) {
        first = it->position;
        second = next->position;
      }
    }
  }
  if (second < 0) return {};
  const int other = static_cast<int>(first / per), t = static_cast<int>(second / per);
  const Simplex f = outward_facet_array(mesh.cells[t]).facet[second % per];
  const std::string cells = mesh.dim == 3 ? "tetrahedra" : "triangles";
  const Simplex a = sorted(mesh.cells[other]), b = sorted(mesh.cells[t]);
  const std::string pair =
      cells + " " + std::to_string(other + 1) + " and " + std::to_string(t + 1) + " (1-based) ";
  if (a == b)
    return {other, t,
            pair + "are one " + mesh.cell_name() + " listed twice (nodes " + node_list(a) +
                "): the body would count twice there"};
  if (mesh.dim == 2)
    return {other, t,
            pair + "overlap: both lie on the same side of their common side from node " +
                std::to_string(f[0] + 1) + " to node " + std::to_string(f[1] + 1)};
  return {other, t,
          pair + "overlap: both lie on the same side of their common face of nodes " +
              node_list(f)};
}

std::pair<int, int> side_with_two_references(const Mesh& mesh) {
  std::unordered_map<FacetKey, int, FacetKeyHash> first; // side -> first facet on it
  for (int e = 0; e < static_cast<int>(mesh.facets.size()); ++e) {
    const Facet& facet = mesh.facets[e];
    const auto [it, fresh] = first.try_emplace(facet_key(facet.node), e);
    if (!fresh && mesh.facets[it->second].ref != facet.ref) return {it->second, e};
  }
  return {-1, -1};
}

int orient_facets(Mesh& mesh) {
  struct Side {
    Simplex outward; ///< as in the first cell met
    int count = 0;
  };
  // Only the referenced sides are looked up (a cell's facet whose nodes are not all on referenced
  // facets is skipped without hashing): the cells are scanned once, in order.
  std::unordered_map<FacetKey, Side, FacetKeyHash> sides;
  sides.reserve(mesh.facets.size());
  for (const Facet& facet : mesh.facets)
    sides.try_emplace(facet_key(facet.node));
  const std::vector<char> on = nodes_on_facets(mesh);
  if (!sides.empty())
    for (const auto& cell : mesh.cells)
      for (const Simplex& f : outward_facet_array(cell)) {
        if (!all_marked(on, f)) continue;
        const auto it = sides.find(facet_key(f));
        if (it == sides.end()) continue;
        if (it->second.count++ == 0) it->second.outward = f;
      }
  std::vector<Facet> kept;
  kept.reserve(mesh.facets.size());
  std::unordered_set<FacetKey, FacetKeyHash> seen;
  for (std::size_t e = 0; e < mesh.facets.size(); ++e) {
    Facet facet = mesh.facets[e];
    const auto it = sides.find(facet_key(facet.node));
    if (it->second.count == 0) return static_cast<int>(e);
    if (!seen.insert(it->first).second) continue;
    if (it->second.count == 1) facet.node = it->second.outward;
    kept.push_back(facet);
  }
  mesh.facets = std::move(kept);
  return -1;
}

std::vector<int> drop_unused_nodes(Mesh& mesh) {
  std::vector<int> renumber(mesh.nodes.size(), -1);
  for (const auto& cell : mesh.cells) {
    for (int v : cell)
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
  for (auto& cell : mesh.cells) {
    for (int& v : cell)
      v = renumber[v];
  }
  for (auto& facet : mesh.facets) {
    for (int& v : facet.node)
      v = renumber[v];
  }
  return renumber;
}

std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh) {
  std::vector<std::pair<int, int>> pairs;
  if (mesh.nodes.empty()) return pairs;
  Point low = mesh.nodes.front(), high = low;
  for (const Point& x : mesh.nodes) {
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
