#pragma once
// The dense kernels of the condensed contact problems by BLAS and LAPACK (OpenBLAS here: blocked
// and vectorized for the machine, where Eigen's kernels are built for SSE2 only): the Cholesky
// factorization (dpotrf, three to four times Eigen's own LLT on the 1026 x 1026 matrices of the
// Hertz problem at N = 512), the LU of the coupled (frictional) tail systems (dgetrf) and the
// symmetric rank-k updates of the tails' Schur complements (dsyrk).
#include <Eigen/Core>
#include <Eigen/LU>

#include <vector>

namespace sig {

/// Dense matrices of this many rows on go to BLAS and LAPACK, smaller ones keep Eigen's kernels:
/// the 3D contact zones' tails (2000-5000 unknowns) are where Eigen's products and LU cost, and
/// the 2D scenes' small tails keep the rounding their results were recorded with (the DS files
/// of scenes 6 and 7a --quick stay bit for bit).
inline constexpr Eigen::Index blas_min_rows = 1024;

/// H := H + alpha P P^T by dsyrk on H's lower triangle, the strict upper triangle then set from
/// it: H exactly symmetric, so that a row of H may be read as its column (contiguous).
void add_gram(Eigen::Ref<Eigen::MatrixXd> H, double alpha,
              const Eigen::Ref<const Eigen::MatrixXd>& P);

/// A := L with A = L L^T, L in the lower triangle (the strict upper triangle left as it was);
/// false if A is not positive definite.
bool cholesky_in_place(Eigen::MatrixXd& A);

/// LU with partial pivoting of a square matrix: Eigen's PartialPivLU below `blas_min_rows` rows,
/// LAPACK's dgetrf from there on. On the frictional 3D half ball (issue 26) the contact
/// zone's tail system has 2000-3000 unknowns and is factorized at every Newton iteration, where
/// Eigen's matrix kernels (its LU's among them) took about a quarter of the dense Newton's time
/// (perf, 66366 dofs); smaller tails keep Eigen's (the DS files of scenes 7a and 7b --quick
/// stayed bit for bit).
class DenseLu {
public:
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
