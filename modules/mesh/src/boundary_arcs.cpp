#include "mesh/boundary_arcs.hpp"

namespace sig {

Eigen::Vector2d onto_boundary(const std::vector<BoundaryArc>& arcs, int ref,
                              const Eigen::Vector2d& x) {
  for (const BoundaryArc& arc : arcs)
    if (arc.ref == ref) {
      const Eigen::Vector2d d = x - arc.centre;
      // A chord's midpoint is never the centre (a half circle's chord is the half disc's top,
      // which carries another reference).
      return arc.centre + arc.radius * d / d.norm();
    }
  return x;
}

} // namespace sig
