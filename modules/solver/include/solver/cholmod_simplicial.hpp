#pragma once
// A simplicial CHOLMOD LL^T (METIS order) and its plain solve with a reused workspace: the
// fastest forward-backward solve CHOLMOD gives on the 2D meshes of the quasistatic march, the
// floor that sig-bench-quasistatic measures a step against (drivers/bench-scene5.sh). The
// project's CholmodSolver is supernodal, whose substitutions cost about twice as much there (many
// small supernodes, one BLAS call each), so a floor taken with it would flatter the march.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace sig {

class CholmodSimplicialSolver {
public:
  /// A: symmetric positive definite, stored full (its lower triangle is read), compressed.
  /// sig::Error if it is not positive definite.
  explicit CholmodSimplicialSolver(const Eigen::SparseMatrix<double>& A);
  ~CholmodSimplicialSolver();
  CholmodSimplicialSolver(const CholmodSimplicialSolver&) = delete;
  CholmodSimplicialSolver& operator=(const CholmodSimplicialSolver&) = delete;

  /// A^-1 b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace sig
