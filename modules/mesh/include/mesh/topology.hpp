#pragma once
// Small operations the mesh readers and generators share: the keys of edges and facets, the
// positive orientation of cells (counter-clockwise triangles, right-handed tetrahedra), the
// orientation of referenced facets (outward on the boundary) and the removal of nodes no cell
// uses. Each works in 2D and 3D alike.
#include "mesh/mesh.hpp"

#include <array>
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

/// Key of an unordered facet (2 or 3 nodes): its nodes sorted, -1 for the unused third place.
using FacetKey = std::array<int, 3>;
FacetKey facet_key(const Simplex& facet);
struct FacetKeyHash {
  std::size_t operator()(const FacetKey& k) const {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a over the three words
    for (int v : k)
      h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

/// The facets of a positively oriented cell, each oriented outward: local facet j of a triangle
/// is its side from vertex j to vertex j + 1 (the domain on its left, MODULEF's local edge j);
/// of a tetrahedron (v0, v1, v2, v3), facet j is the face opposite vertex (j + 3) % 4... see
/// topology.cpp for the numbering and why.
std::vector<Simplex> outward_facets(const Simplex& cell);

/// outward_facets without allocating, for the loops over every cell of a large mesh.
struct OutwardFacets {
  std::array<Simplex, 4> facet{};
  int count = 0;
  const Simplex* begin() const { return facet.data(); }
  const Simplex* end() const { return facet.data() + count; }
};
OutwardFacets outward_facet_array(const Simplex& cell);

/// Per node of `mesh`: 1 when it is a node of a referenced facet (mesh.facets), else 0. A cell's
/// facet with a node off them is none of the referenced ones: the loops over every cell skip it
/// (all_marked) without a hash look-up.
std::vector<char> nodes_on_facets(const Mesh& mesh);
/// Every node of `f` is marked in `marks` (and in its range).
bool all_marked(const std::vector<char>& marks, const Simplex& f);

/// Make every cell positively oriented (swap its last two nodes), listing the flipped ones in
/// `flipped` if given. Returns -1, or the index of the first degenerate (zero-measure) cell,
/// which no orientation can mend: the readers report it with its line in the file.
int orient_cells(Mesh& mesh, std::vector<int>* flipped = nullptr);

/// orient_cells for the reader of a text mesh file: a degenerate cell, or two that overlap
/// (find_overlap), is an InputError naming `file` and its line (`lines[c]`), the reoriented ones
/// a warning naming them.
void orient_cells_of_file(Mesh& mesh, const std::string& file, const std::vector<int>& lines);

/// Two cells covering the same ground: listed twice (the same nodes) or folded over one another
/// (on the same side of a common facet). Meshes must tile their domain.
struct CellOverlap {
  int first = -1, second = -1; ///< 0-based, first < second; -1: none
  std::string what;            ///< "triangles 3 and 7 (1-based) ...", "" if none
};
/// The first overlap of the positively oriented cells of `mesh` (orient_cells).
CellOverlap find_overlap(const Mesh& mesh);

/// The first two referenced facets on one side with different references (0-based indices, the
/// second after the first), or {-1, -1}: a side carries one reference (NOPO's edges and faces),
/// so a file giving it two is refused rather than one of them dropped.
std::pair<int, int> side_with_two_references(const Mesh& mesh);

/// Orient every referenced facet that is a facet of exactly one cell as it is in that cell,
/// outward (in 2D: the domain on its left); an interface facet (two cells) keeps its
/// orientation. A repeated facet (same nodes) is kept once, the first occurrence winning.
/// Returns -1, or the index (before removal of repeats) of the first facet that is not a facet
/// of any cell, in which case `mesh` is left unchanged.
int orient_facets(Mesh& mesh);

/// Remove the nodes that no cell uses (gmsh keeps the nodes of unmeshed geometry points) and
/// renumber, keeping the order of the others. Returns the new index of each old node (-1 =
/// removed). Facets must only use cell nodes (see orient_facets).
std::vector<int> drop_unused_nodes(Mesh& mesh);

/// Pairs of distinct nodes closer than 1e-10 of the mesh's size (0-based, sorted): unless the
/// cells share them, an open crack where the file meant one node.
std::vector<std::pair<int, int>> coincident_nodes(const Mesh& mesh);

/// A reader's warning that it changed what the file said, naming the entities (at most 10, then
/// "..."): "FILE: reoriented 3 clockwise triangle(s) (1-based): 4, 9, 12".
void warn_entities(const std::string& file, const std::string& what,
                   const std::vector<long>& numbers, const std::string& action);

} // namespace sig
