#pragma once
// The dense factorizations of the condensed contact problems by LAPACK (OpenBLAS here: blocked
// and vectorized for the machine, where Eigen's kernels are built for SSE2 only): the Cholesky
// factorization (dpotrf, three to four times Eigen's own LLT on the 1026 x 1026 matrices of the
// Hertz problem at N = 512) and the LU of the coupled (frictional) tail systems (dgetrf).
#include <Eigen/Core>
#include <Eigen/LU>

#include <vector>

namespace sig {

/// A := L with A = L L^T, L in the lower triangle (the strict upper triangle left as it was);
/// false if A is not positive definite.
bool cholesky_in_place(Eigen::MatrixXd& A);

/// LU with partial pivoting of a square matrix: Eigen's PartialPivLU below `lapack_min_rows`
/// rows, LAPACK's dgetrf from there on. On the frictional 3D half ball (issue 26) the contact
/// zone's tail system has 2000-3000 unknowns and is factorized at every Newton iteration, where
/// Eigen's matrix kernels (its LU's among them) took about a quarter of the dense Newton's time
/// (perf, 66366 dofs); smaller tails keep Eigen's (the DS files of scenes 7a and 7b --quick
/// stayed bit for bit).
class DenseLu {
public:
  static constexpr Eigen::Index lapack_min_rows = 1024;
  void compute(const Eigen::MatrixXd& A);
  /// A^-1 b; non-finite entries if A is singular.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

private:
  Eigen::PartialPivLU<Eigen::MatrixXd> small_;
  Eigen::MatrixXd factors_; ///< dgetrf's L and U
  std::vector<int> pivots_; ///< dgetrf's row interchanges (1-based)
  bool lapack_ = false;
  bool singular_ = false;
};

} // namespace sig
