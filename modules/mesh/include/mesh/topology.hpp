#pragma once
// Small operations the mesh readers and generators share: the key of an unordered edge, the
// counter-clockwise orientation of triangles, the orientation of referenced edges (domain on the
// left) and the removal of nodes no triangle uses.
#include "mesh/mesh.hpp"

#include <cstdint>
#include <vector>

namespace sig {

/// Key of the unordered pair {a, b} of node indices (>= 0).
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return (lo << 32) | hi;
}

/// Reverse every clockwise triangle (swap its last two nodes). Returns -1, or the index of the
/// first degenerate (zero-area) triangle, which no orientation can mend: the readers report it
/// with its line in the file.
int orient_counter_clockwise(Mesh& mesh);

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

} // namespace sig
