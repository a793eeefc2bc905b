#pragma once
// Dirichlet conditions by elimination: with the dofs split into free (f) and imposed (d), the
// problem K u = f with u_d given becomes
//     K_ff u_f = f_f - K_fd u_d,
// which keeps K_ff symmetric positive definite (a Cholesky factorization applies) and drops the
// reactions, which are recovered as K_d. u - f_d when needed.
#include "assembly/system.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace sig {

struct ReducedSystem {
  Eigen::SparseMatrix<double> K;  ///< K_ff
  Eigen::VectorXd f;              ///< f_f - K_fd u_d at t = 0
  TimeLoads time_loads;           ///< the change of f_f in time (assembly/time_loads.hpp)
  std::vector<int> free_dofs;     ///< sorted; reduced index -> full dof
  std::vector<int> reduced_index; ///< full dof -> reduced index, -1 for an imposed dof
  std::vector<int> dirichlet_dofs;
  Eigen::VectorXd dirichlet_values;

  int num_free() const { return static_cast<int>(free_dofs.size()); }
  int num_full() const { return static_cast<int>(reduced_index.size()); }
  /// f at time t: f + the free part of time_loads.change(t).
  Eigen::VectorXd load_at(double t) const;
  /// The full vector: u_free on the free dofs, the imposed values on the others.
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const;
  /// The free part of a full vector.
  Eigen::VectorXd restrict(const Eigen::VectorXd& full) const;
  /// The reduced index of the first of the d dofs of a contact node (0-based mesh node) of a
  /// d-dimensional body (dofs d node + component), its others following it (the free dofs keep
  /// their order); sig::Error naming the node and the component if one is imposed: Gamma3 and
  /// Gamma1 share no node.
  int contact_node_first_dof(int node, int d) const;
  /// A_ff of a full matrix (e.g. the mass matrix for dynamics), same storage as K.
  Eigen::SparseMatrix<double> restrict_matrix(const Eigen::SparseMatrix<double>& A) const;
};

/// Eliminate the Dirichlet dofs of `system` (elimination above), but those of `imposed_elsewhere`
/// (sorted): their conditions are imposed by another part of the solve (a component of a contact
/// node held in the node's frame by the contact solver), so they stay free unknowns.
ReducedSystem reduce(const LinearSystem& system, const std::vector<int>& imposed_elsewhere = {});

} // namespace sig
