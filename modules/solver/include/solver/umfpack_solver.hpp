#pragma once
// UMFPACK adapter: sparse LU with partial pivoting for any square matrix, METIS ordering.
// Used for unsymmetric systems (unsymmetric augmented Lagrangian Jacobians) and as a check of
// the symmetric backends.
#include "solver/linear_solver.hpp"

#include <memory>

namespace sig {

class UmfpackSolver final : public LinearSolver {
public:
  explicit UmfpackSolver(MatrixKind kind = MatrixKind::general);
  ~UmfpackSolver() override;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  using LinearSolver::solve;
  void analyze(const Eigen::SparseMatrix<double>& A) override;
  /// Throws sig::Error if UMFPACK finds the matrix singular.
  void factorize(const Eigen::SparseMatrix<double>& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  std::string name() const override { return "umfpack"; }
  /// Ordering used by the last analysis ("metis", "amd", ...); empty before analyze().
  std::string ordering() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace sig
