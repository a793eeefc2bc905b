#pragma once
// The dense Cholesky factorization of the condensed contact problems, by LAPACK's dpotrf
// (OpenBLAS here: blocked and vectorized for the machine, three to four times Eigen's own LLT on
// the 1026 x 1026 matrices of the Hertz problem at N = 512).
#include <Eigen/Core>

namespace sig {

/// A := L with A = L L^T, L in the lower triangle (the strict upper triangle left as it was);
/// false if A is not positive definite.
bool cholesky_in_place(Eigen::MatrixXd& A);

} // namespace sig
