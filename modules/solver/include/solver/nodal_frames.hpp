#pragma once
// Nodal frames at contact nodes, shared by the small- and large-deformation contact solves: the
// unknowns of a contact node become (w_t, w_n), its slip and its normal displacement towards the
// obstacle, u = R w on the node's two dofs and u = w elsewhere (u = Q w, Q orthogonal).
#include "contact/contact_law.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

/// The frame of one contact node of outward obstacle normal n: its columns are the contact
/// tangent t = (n2, -n1) (contact/contact_law.hpp) and -n, so that u = R w takes w = (w_t, w_n):
/// w_t the slip along t, w_n the normal displacement towards the obstacle. R is orthogonal.
inline Eigen::Matrix2d nodal_frame(const Eigen::Vector2d& n) {
  Eigen::Matrix2d R;
  R.col(0) = contact_tangent(n);
  R.col(1) = -n;
  return R;
}

/// Q applied in place, on the values of a sparse matrix whose pattern holds the full 2 x 2 block
/// of every contact node: Q^T A Q has A's pattern, since Q only mixes the two dofs of a node, so
/// the rotation costs a pass over those nodes' rows and columns, with no matrix product and no
/// new pattern.
class FrameRotation {
public:
  /// `first_dofs[p]`: the dof a of contact node p, whose two dofs are a and a + 1 (column-major,
  /// compressed A with sorted rows). sig::Error if a node's block is not full in A.
  FrameRotation(const Eigen::SparseMatrix<double>& A, std::vector<int> first_dofs);

  /// A := Q^T A Q for the frames of `normals` (one per contact node); A has the pattern of the
  /// constructor's.
  void rotate(Eigen::SparseMatrix<double>& A, const std::vector<Eigen::Vector2d>& normals) const;
  /// v := Q^T v (into the frames) or v := Q v (back).
  void to_frames(Eigen::VectorXd& v, const std::vector<Eigen::Vector2d>& normals) const;
  void from_frames(Eigen::VectorXd& v, const std::vector<Eigen::Vector2d>& normals) const;

  /// (A w)[a + 1], the normal row of contact node p.
  double normal_row_times(const Eigen::SparseMatrix<double>& A, int p,
                          const Eigen::VectorXd& w) const;

private:
  std::vector<int> first_;                  ///< dof a of contact node p
  std::vector<std::vector<int>> row_slots_; ///< per node: slot of row a in each column of a
};

} // namespace sig
