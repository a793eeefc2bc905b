#pragma once
// CHOLMOD adapter: supernodal LL^T of a symmetric positive definite matrix, METIS nested
// dissection ordering (AMD when CHOLMOD was built without METIS). The matrix is given full;
// only its lower triangle is read.
#include "solver/linear_solver.hpp"

#include <memory>

namespace sig {

class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver();
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  using LinearSolver::solve;
  void analyze(const Eigen::SparseMatrix<double>& A) override;
  /// Throws sig::Error naming the failing leading minor if A is not positive definite.
  void factorize(const Eigen::SparseMatrix<double>& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override;
  std::string name() const override { return "cholmod"; }
  /// Ordering used by the last analysis: "metis" or "amd"; empty before analyze().
  std::string ordering() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace sig
