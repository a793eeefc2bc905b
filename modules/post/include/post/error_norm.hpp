#pragma once
// The error of a P1 solution against a reference solution on a finer mesh, in the norm of V
// (ALGORITHMS.md 0.6; thesis (2.6), (u, v)_V = integral of eps(u) . eps(v), l.3041):
//   ||u_ref - P u_h||_V = ||eps(u_ref - P u_h)||_L2(Omega), integrated on the reference mesh,
// P the P1 interpolation of the coarse field at the reference mesh's nodes. On nested meshes
// (each coarse triangle a union of reference triangles: the structured squares of Figs 4.7,
// 5.12 and 6.5 refined by halving) P u_h is the coarse field itself and the norm is exact. On
// other meshes P u_h is its interpolant on the reference mesh, and a reference node outside
// every coarse triangle (a curved boundary, where the coarse chords cut the circle) takes the
// affine extension of the coarse triangle it is closest to.
#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <optional>

namespace sig {

/// P u: the coarse P1 field `u` (2 values per coarse node) at the nodes of `fine`.
Eigen::VectorXd prolongate(const Mesh& coarse, const Eigen::VectorXd& u, const Mesh& fine);

struct StrainError {
  double error = 0;          ///< ||eps(u_ref - P u_h)||_L2
  double reference_norm = 0; ///< ||eps(u_ref)||_L2
  double relative() const { return reference_norm > 0 ? error / reference_norm : error; }
};

/// A sub-domain [x0, x1] x [y0, y1]: the norms integrate the reference triangles whose centroid
/// lies in it. An error away from the corners where the solution leaves H^2 (a clamped side
/// meeting a loaded one) shows the rate the discretisation has where the solution is smooth.
struct Window {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool contains(const Eigen::Vector2d& x) const {
    return x.x() >= x0 && x.x() <= x1 && x.y() >= y0 && x.y() <= y1;
  }
};

/// The error of u_h (on `coarse`) against u_ref (on `reference`), header; on the whole domain,
/// or on `window`'s triangles. sig::Error for sizes that do not match the meshes, or a window
/// that holds no reference triangle.
StrainError strain_error(const Mesh& reference, const Eigen::VectorXd& u_ref, const Mesh& coarse,
                         const Eigen::VectorXd& u_h, const std::optional<Window>& window = {});

} // namespace sig
