#pragma once
// Conforming refinement of marked triangles by bisection, for the adaptive loop (issue 29):
// every triangle's refinement edge is its longest edge (Rivara's longest-edge bisection, M.-C.
// Rivara, IJNME 20 (1984) 745-756: the angles stay bounded below by half the mesh's smallest,
// whatever the number of refinements; the edge is recomputed from the geometry, so a mesh read
// back from a file needs no stored newest vertex). A marked triangle's three edges are bisected
// (it is cut into 4, its sides halved: every triangle marked is a uniform refinement); so is the
// refinement edge of every triangle one of whose edges is bisected (the closure that keeps the
// mesh conforming: no hanging node); each triangle is then cut into 2, 3 or 4 by bisecting its
// refinement edge first. Sub-domains pass to the children, a referenced
// edge's reference to its halves; a new node on an edge of a curved boundary goes onto the
// circle (mesh/boundary_arcs.hpp).
#include "mesh/boundary_arcs.hpp"
#include "mesh/mesh.hpp"

#include <vector>

namespace sig {

struct Bisection {
  Mesh mesh;
  int bisected_edges = 0; ///< the new nodes: one per bisected edge
};

/// The refinement of `mesh` that bisects the triangles `marked` (0-based, any order, repeats
/// allowed) and what conformity asks for. sig::Error, before anything is allocated, when the
/// refined mesh would have more than `max_nodes` nodes (mesh/mesh.hpp max_mesh_nodes), naming
/// both counts.
Bisection bisect(const Mesh& mesh, const std::vector<int>& marked,
                 const std::vector<BoundaryArc>& arcs = {}, double max_nodes = max_mesh_nodes);

} // namespace sig
