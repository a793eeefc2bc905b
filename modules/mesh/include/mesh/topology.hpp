#pragma once
// Small operations the mesh readers and generators share: the key of an unordered edge, the
// counter-clockwise orientation of triangles, the orientation of referenced edges (domain on the
// left) and the removal of nodes no triangle uses.
#include "mesh/mesh.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sig {

/// Key of the unordered pair {a, b} of node indices (>= 0).
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return (lo << 32) | hi;
}

/// Reverse every clockwise triangle (swap its last two nodes), listing them in `flipped` if
/// given. Returns -1, or the index of the first degenerate (zero-area) triangle, which no
/// orientation can mend: the readers report it with its line in the file.
int orient_counter_clockwise(Mesh& mesh, std::vector<int>* flipped = nullptr);

/// orient_counter_clockwise for the reader of a text mesh file: a degenerate triangle, or two
/// that overlap (find_overlap), is an InputError naming `file` and its line (`lines[t]`), the
/// reoriented ones a warning naming them.
void orient_triangles_of_file(Mesh& mesh, const std::string& file, const std::vector<int>& lines);

/// Two triangles covering the same ground: listed twice (the same three nodes) or folded over
/// one another (on the same side of a common side). Meshes must tile their domain.
struct TriangleOverlap {
  int first = -1, second = -1; ///< 0-based, first < second; -1: none
  std::string what;            ///< "triangles 3 and 7 (1-based) ...", "" if none
};
/// The first overlap of the counter-clockwise triangles of `mesh` (orient_counter_clockwise).
TriangleOverlap find_overlap(const Mesh& mesh);

/// The first two referenced edges on one side with different references (0-based indices, the
/// second after the first), or {-1, -1}: a side carries one reference (NOPO's edges), so a file
/// giving it two is refused rather than one of them dropped.
std::pair<int, int> side_with_two_references(const Mesh& mesh);

/// Point every referenced edge that is a side of exactly one triangle in the direction it has in
/// that (counter-clockwise) triangle, so the domain lies on its left; an interface edge (two
/// triangles) keeps its direction. A repeated edge (same node pair) is kept once, the first
/// occurrence winning. Returns -1, or the index (before removal of repeats) of the first edge
/// that is not a side of any triangle, in which case `mesh` is left unchanged.
int orient_boundary_edges(Mesh& mesh);

/// Remove the nodes that no triangle uses (gmsh keeps the nodes of unmeshed geometry points) and
/// renumber, keeping the order of the others. Returns the new index of each old node (-1 =
/// removed). Edges must only use triangle nodes (see orient_boundary_edges).
std::vector<int> drop_unused_nodes(Mesh& mesh);

/// Pairs of distinct nodes closer than 1e-10 of the mesh's size (0-based, sorted): unless the
/// triangles share them, an open crack where the file meant one node.
std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh);

/// A reader's warning that it changed what the file said, naming the entities (at most 10, then
/// "..."): "FILE: reoriented 3 clockwise triangle(s) (1-based): 4, 9, 12".
void warn_entities(const std::string& file, const std::string& what,
                   const std::vector<long>& numbers, const std::string& action);

} // namespace sig
