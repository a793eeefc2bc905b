#pragma once
// The dense kernels of the condensed contact problems by BLAS and LAPACK (OpenBLAS here: blocked
// and vectorized for the machine, where Eigen's kernels are built for SSE2 only): the Cholesky
// factorization (dpotrf, three to four times Eigen's own LLT on the 1026 x 1026 matrices of the
// Hertz problem at N = 512), the LU of the coupled (frictional) tail systems (dgetrf) and the
// symmetric rank-k updates of the tails' Schur complements (dsyrk), the products L L^T of a
// triangular factor (dlauum).
#include <Eigen/Core>
#include <Eigen/LU>

#include <vector>

namespace sig {

/// Dense matrices of this many rows on go to BLAS and LAPACK, smaller ones keep Eigen's kernels:
/// the 3D contact zones' tails (1500-2000 unknowns at 28887 dofs, 4596 condensed at 158280) are
/// where Eigen's products and LU cost, and the 2D scenes' small tails keep the rounding their
/// results were recorded with (the DS files of scenes 6 and 7a --quick stay bit for bit).
inline constexpr Eigen::Index blas_min_rows = 1024;

/// H := H + alpha P P^T by dsyrk on H's lower triangle, the strict upper triangle then set from
/// it: H exactly symmetric, so that a row of H may be read as its column (contiguous).
void add_gram(Eigen::Ref<Eigen::MatrixXd> H, double alpha,
              const Eigen::Ref<const Eigen::MatrixXd>& P);

/// S X for a symmetric S of which the lower triangle is read (dsymm).
Eigen::MatrixXd symmetric_product(const Eigen::MatrixXd& S, const Eigen::MatrixXd& X);

/// L L^T of the lower triangle of L (its strict upper triangle unread), exactly symmetric: LAPACK's
/// dlauum (U U^T of an upper triangular U) on L's entries in reverse order, a third of the flops
/// of dsyrk on L's square.
Eigen::MatrixXd triangular_gram(const Eigen::Ref<const Eigen::MatrixXd>& L);

/// A := L with A = L L^T, L in the lower triangle (the strict upper triangle left as it was);
/// false if A is not positive definite.
bool cholesky_in_place(Eigen::MatrixXd& A);

/// Row-major: the tail systems are built a row at a time.
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// LU with partial pivoting of a square matrix: Eigen's PartialPivLU, or LAPACK's dgetrf on A's
/// rows (A^T column-major, solved transposed) when the caller asks: for a tail of `blas_min_rows`
/// unknowns or more, whatever the size of its system (the free unknowns, 700-1000 of the
/// 1500-2000 of a frictional tail at 28887 dofs, went to Eigen's LU when the system's size chose).
class DenseLu {
public:
  void compute(const RowMatrixXd& A, bool lapack);
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
