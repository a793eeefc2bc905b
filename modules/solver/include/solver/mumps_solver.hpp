#pragma once
// MUMPS adapter on this process alone (MPI_COMM_SELF, solver/mpi_session.hpp): multifrontal LDL^T
// (SYM = 1 spd, 2 symmetric) or LU (SYM = 0), AMD ordering up to 2e5 unknowns (a 2D problem's
// analysis 4-8x cheaper than nested dissection's for the same factorization time), MUMPS's
// automatic choice above.
//
// With Schur variables on 3D rows it gives MUMPS METIS's nested dissection as PERM_IN (MUMPS
// 5.5 takes AMD with a Schur complement), in one process and over the ranks alike.
//
// With Schur variables it performs MUMPS's partial factorization (ICNTL(19)): the interior
// block K_ii is factorized and S = K_cc - K_ci K_ii^{-1} K_ic comes out of the same pass. Solves
// then act on the interior problem only: x_i = K_ii^{-1} b_i and x_c = 0 (ICNTL(26) = 0); or a
// full solve is split around the Schur problem, reduce() then expand() (ICNTL(26) = 1, 2), for
// the cost of one solve.
#include "solver/linear_solver.hpp"
#include "solver/mumps_statistics.hpp"

#include <memory>
#include <vector>

namespace sig {

class MumpsSolver final : public LinearSolver {
public:
  /// schur_dofs: sorted 0-based variables kept out of the factorization; empty for a plain
  /// solver. `rank_rows`: the solver of every rank of an mpirun job (MPI_COMM_WORLD), each rank
  /// giving the rows it holds (the matrices passed hold only those, the other rows empty; the
  /// calls are collective); right sides are the host's (rank 0), and the solutions, the Schur
  /// complement and the reduced right sides come back on every rank.
  explicit MumpsSolver(MatrixKind kind, std::vector<int> schur_dofs = {}, bool rank_rows = false);
  ~MumpsSolver() override;
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  using LinearSolver::solve;
  void analyze(const Eigen::SparseMatrix<double>& A) override;
  /// Throws sig::Error with INFOG(1) and INFOG(2) on failure; workspace shortages (-8, -9,
  /// -14, -15) are retried with a larger ICNTL(14) first.
  void factorize(const Eigen::SparseMatrix<double>& A) override;
  /// MUMPS keeps its solve workspace in the instance: solve() is const for the caller but two
  /// threads must not solve with the same instance at once.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override;
  std::string name() const override { return "mumps"; }
  /// Ordering used by the last analysis (INFOG(7)): "metis", "scotch", "pord", "amd", ...
  std::string ordering() const;
  /// MUMPS's statistics of the last factorization, every rank's gathered on each.
  const MumpsStatistics& statistics() const;
  /// The Schur complement of the last factorization (full symmetric matrix for SYM > 0),
  /// rows and columns in the order of schur_dofs.
  Eigen::MatrixXd schur_complement() const;
  /// The condensation of one right side b (all n variables) in half a solve (ICNTL(26) = 1, the
  /// forward elimination): the reduced right side b_c - K_ci K_ii^{-1} b_i on the Schur
  /// variables (schur_dofs order). MUMPS keeps the eliminated b for the next expand().
  Eigen::VectorXd reduce(const Eigen::VectorXd& b) const;
  /// The whole solution for the last reduce()'s b and the Schur variables' values x_c (the
  /// solution of S x_c = reduce(b)), in the other half (ICNTL(26) = 2, the backward
  /// substitution); x_c kept on its variables. One expand() per reduce().
  Eigen::VectorXd expand(const Eigen::VectorXd& x_schur) const;

private:
  /// The `columns` right sides of `rows` entries at x (column-major) become the solutions.
  void solve_in_place(double* x, int rows, int columns) const;

  struct State;
  std::unique_ptr<State> state_;
};

} // namespace sig
