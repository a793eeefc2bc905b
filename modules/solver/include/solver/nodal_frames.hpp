#pragma once
// Nodal frames at contact nodes, shared by the small- and large-deformation contact solves.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace sig {

/// The frame of one contact node of outward obstacle normal n: its columns are the contact
/// tangent t = (n2, -n1) (contact/contact_law.hpp) and -n, so that u = R w takes w = (w_t, w_n):
/// w_t the slip along t, w_n the normal displacement towards the obstacle. R is orthogonal.
inline Eigen::Matrix2d nodal_frame(const Eigen::Vector2d& n) {
  Eigen::Matrix2d R;
  R << n.y(), -n.x(), -n.x(), -n.y();
  return R;
}

/// The rotation u = Q w of an n-dof vector: the block nodal_frame(normals[p]) on the two dofs
/// dofs[p] of contact node p, the identity elsewhere. Q is orthogonal.
Eigen::SparseMatrix<double> nodal_frames(int n, const std::vector<std::array<int, 2>>& dofs,
                                         const std::vector<Eigen::Vector2d>& normals);

} // namespace sig
