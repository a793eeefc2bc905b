#pragma once
// Nodal frames at contact nodes, shared by the small- and large-deformation contact solves.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace sig {

/// The rotation u = Q w of an n-dof vector: at contact node p, whose two dofs are dofs[p], the
/// pair becomes (w_t, w_n) = (t_p . u_p, -n_p . u_p) with t_p = (-n2, n1), so that the normal
/// displacement u_n,p (towards the obstacle of outward normal n_p) is the unknown in the place
/// of u2; elsewhere Q is the identity. Q is orthogonal.
Eigen::SparseMatrix<double> nodal_frames(int n, const std::vector<std::array<int, 2>>& dofs,
                                         const std::vector<Eigen::Vector2d>& normals);

} // namespace sig
