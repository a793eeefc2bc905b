#pragma once
// The generalized Jacobian of the large-deformation contact Newton
// (stages/finite_strain_contact.hpp) on ONE sparsity pattern for the whole solve, so that the
// linear solver analyzes it once (DESIGN.md: symbolic analysis reused across iterations) and each
// iteration costs one numeric factorization:
//  - the nodal frames u = Q w (nodal_frames.hpp) are applied in place to the tangent's values:
//    Q^T K Q has K's pattern, since Q only mixes the d dofs of a contact node, whose d x d
//    node blocks are full;
//  - the Dirichlet dofs of the problem, fixed for the solve, are eliminated;
//  - the normal dofs held by an active set (du_n = -phi), which change from one iteration to the
//    next, are not eliminated but decoupled: their row and column are zeroed except the diagonal
//    d, and the right side is d times the held value. The free block is the matrix elimination
//    would give, so the solution is elimination's, on an unchanged pattern.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/nodal_frames.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace sig {

class LinearSolver;

class NewtonMatrix {
public:
  /// `pattern`: a compressed matrix, structurally symmetric with sorted indices, whose stored
  /// entries are the pattern (its values are ignored; the assembly's SparsityPattern::zero_matrix()
  /// is one); `dirichlet[i]` marks the dofs fixed for the whole solve; `contact_nodes` the nodes
  /// whose d dofs (d = 2 or 3, dof = d node + component) are rotated into nodal frames. sig::Error
  /// if a contact node's block is not full.
  NewtonMatrix(Eigen::SparseMatrix<double> pattern, const std::vector<char>& dirichlet,
               const std::vector<int>& contact_nodes, int d = 2);

  /// Start from the bulk tangent K (on the pattern of the constructor) without a copy: the
  /// matrix takes K's storage and K gets the previous matrix's (same pattern, stale values), for
  /// a caller that assembles K anew before reading it again.
  void take_tangent(Eigen::SparseMatrix<double>& K);
  /// (dofs of contact node p, same) += block, before the rotation.
  void add_node_block(int p, const Eigen::Ref<const Eigen::MatrixXd>& block);
  /// The matrix becomes Q^T A Q with the frames of these normals (one per contact node; 2D).
  void rotate(const std::vector<Eigen::Vector2d>& normals);
  /// The same with these frames (contact_frame of each node's normal; d x d).
  void rotate(const std::vector<ContactFrame>& frames);
  /// The diagonal entry of a dof, to add a spring after the rotation.
  double& diagonal(int dof) { return full_.valuePtr()[diagonal_[dof]]; }
  /// Entry (row, column), which must be on the pattern (sig::Error otherwise).
  double& entry(int row, int column) { return value(row, column); }
  /// Row `target` += factor x row `source`, both dofs of one node (their rows share the pattern):
  /// a force law coupled to another component's reaction, after the rotation.
  void add_row(int target, int source, double factor);

  /// Solve A dw = -r0 with dw = value on the imposed dofs (sorted by dof: the problem's
  /// Dirichlet dofs and the held normal dofs); returns the whole dw, the imposed values exact.
  Eigen::VectorXd solve(const Eigen::VectorXd& r0,
                        const std::vector<std::pair<int, double>>& imposed, LinearSolver& solver);
  /// (A dw)[b] on the normal dof b = d node + d - 1 of contact node p: its reaction.
  double normal_row_times(int p, const Eigen::VectorXd& dw) const;
  /// (A dw)[dof] for any dof (a reaction of an imposed component).
  double row_times(int dof, const Eigen::VectorXd& dw) const;

  /// A, the rotated matrix with the method's terms, on the full pattern (for tests).
  const Eigen::SparseMatrix<double>& matrix() const { return full_; }

private:
  double& value(int row, int column);
  /// The slot of (row, column) in full_, or -1 off the pattern.
  int slot(int row, int column) const;

  Eigen::SparseMatrix<double> full_;      ///< Q^T K Q + the method's terms, K's pattern
  int d_;                                 ///< dofs a node
  Eigen::SparseMatrix<double> reduced_;   ///< its free rows and columns: the factorized matrix
  std::vector<int> nodes_;                ///< contact node p
  std::vector<int> free_dofs_;            ///< reduced index -> dof
  std::vector<int> free_index_;           ///< dof -> reduced index, -1 for a Dirichlet dof
  std::vector<int> source_;               ///< slot of reduced_ -> slot of full_
  std::vector<int> diagonal_;             ///< dof -> slot of its diagonal entry
  std::unique_ptr<FrameRotation> frames_; ///< the nodal frames, in place on full_
  Eigen::VectorXd moved_;                 ///< solve()'s A(:, imposed) values, kept allocated
};

} // namespace sig
