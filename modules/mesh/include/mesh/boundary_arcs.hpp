#pragma once
// The curved parts of a generated mesh's boundary: the circle each referenced boundary edge of a
// disc, half disc or ring lies on. A refinement puts a new node of such an edge on the circle
// (the generators' own arcs, generators_gmsh.cpp), not on the chord, so that refined meshes
// converge to the true domain.
#include <Eigen/Core>

#include <vector>

namespace sig {

struct BoundaryArc {
  int ref = 0; ///< the reference of the edges on this circle
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
};

/// x moved radially onto the circle of the arc of reference `ref`, or x itself when no arc has
/// that reference (a straight side, an interface, a mesh file's polygon).
Eigen::Vector2d onto_boundary(const std::vector<BoundaryArc>& arcs, int ref,
                              const Eigen::Vector2d& x);

} // namespace sig
