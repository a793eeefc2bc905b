#pragma once
// Nodal frames at contact nodes, shared by the small- and large-deformation contact solves: the
// unknowns of a contact node become w = (slips, w_n), its slips along its tangents and its normal
// displacement towards the obstacle, u = R w on the node's d dofs and u = w elsewhere (u = Q w, Q
// orthogonal). R is contact_frame(n) (contact/contact_law.hpp), d x d in d = 2 or 3.
#include "contact/contact_law.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

/// The frame of one contact node of a 2D body, of outward obstacle normal n: its columns are the
/// contact tangent t = (n2, -n1) (contact/contact_law.hpp) and -n, so that u = R w takes w =
/// (w_t, w_n): w_t the slip along t, w_n the normal displacement towards the obstacle. R is
/// orthogonal; contact_frame(n) in 2D.
inline Eigen::Matrix2d nodal_frame(const Eigen::Vector2d& n) {
  Eigen::Matrix2d R;
  R.col(0) = contact_tangent(n);
  R.col(1) = -n;
  return R;
}

/// The 2D frames of `normals`, as contact frames.
std::vector<ContactFrame> frames_of(const std::vector<Eigen::Vector2d>& normals);

/// Q applied in place, on the values of a sparse matrix whose pattern holds the full d x d block
/// of every contact node: Q^T A Q has A's pattern, since Q only mixes the d dofs of a node, so
/// the rotation costs a pass over those nodes' rows and columns, with no matrix product and no
/// new pattern.
class FrameRotation {
public:
  /// `first_dofs[p]`: the dof a of contact node p, whose d dofs are a, ..., a + d - 1
  /// (column-major, compressed A with sorted rows). sig::Error if a node's block is not full in A.
  FrameRotation(const Eigen::SparseMatrix<double>& A, std::vector<int> first_dofs, int d = 2);

  /// A := Q^T A Q for the `frames` (one d x d per contact node); A has the pattern of the
  /// constructor's.
  void rotate(Eigen::SparseMatrix<double>& A, const std::vector<ContactFrame>& frames) const;
  /// v := Q^T v (into the frames) or v := Q v (back).
  void to_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const;
  void from_frames(Eigen::VectorXd& v, const std::vector<ContactFrame>& frames) const;
  /// The same with the 2D frames of `normals` (d = 2).
  void rotate(Eigen::SparseMatrix<double>& A, const std::vector<Eigen::Vector2d>& normals) const {
    rotate(A, frames_of(normals));
  }
  void to_frames(Eigen::VectorXd& v, const std::vector<Eigen::Vector2d>& normals) const {
    to_frames(v, frames_of(normals));
  }
  void from_frames(Eigen::VectorXd& v, const std::vector<Eigen::Vector2d>& normals) const {
    from_frames(v, frames_of(normals));
  }

  /// (A w)[a + d - 1], the normal row of contact node p.
  double normal_row_times(const Eigen::SparseMatrix<double>& A, int p,
                          const Eigen::VectorXd& w) const;

private:
  int d_;
  std::vector<int> first_;                  ///< dof a of contact node p
  std::vector<std::vector<int>> row_slots_; ///< per node: slot of row a in each column of a
};

} // namespace sig
