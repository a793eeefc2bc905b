// The dense kernels of solver/dense_cholesky.hpp. The LU of the coupled tail systems, Eigen's and
// LAPACK's (on the row-major A's transpose): both solve A x = b for a nonsymmetric matrix whose
// first pivot needs a row interchange, and a singular one (a zero column) gives non-finite values
// (the caller's test). The Gram products of the tails' Schur complements (P P^T added and L L^T
// of a triangle, exactly symmetric) and the symmetric product S X, against Eigen's products.
#include "solver/dense_cholesky.hpp"

#include <gtest/gtest.h>

#include <random>

namespace sig {
namespace {

RowMatrixXd nonsymmetric(Eigen::Index n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  RowMatrixXd A(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      A(i, j) = value(random);
  A.diagonal().array() += 4.0;
  A(0, 0) = 0; // the first pivot must come from another row
  return A;
}

TEST(DenseLu, EigenAndLapackSolveTheNonsymmetricSystem) {
  for (const Eigen::Index n : {Eigen::Index(40), blas_min_rows + 3})
    for (const bool lapack : {false, true}) {
      const RowMatrixXd A = nonsymmetric(n);
      Eigen::VectorXd x(n);
      for (Eigen::Index k = 0; k < n; ++k)
        x[k] = std::sin(0.3 * double(k)) + 0.2;
      DenseLu lu;
      lu.compute(A, lapack);
      EXPECT_LT((lu.solve(A * x) - x).norm(), 1e-10 * x.norm()) << n << " " << lapack;
      RowMatrixXd singular = A;
      singular.col(n - 1).setZero();
      lu.compute(singular, lapack);
      EXPECT_FALSE(lu.solve(A * x).allFinite()) << n << " " << lapack;
    }
}

TEST(DenseProducts, RankUpdateTriangularAndSymmetricProductsAreTheProducts) {
  const int n = 70;
  const RowMatrixXd random_square = nonsymmetric(n);
  const Eigen::MatrixXd M = random_square; // column-major, nonsymmetric
  const auto P = M.leftCols(9);
  Eigen::MatrixXd H = M + M.transpose();
  const Eigen::MatrixXd expected = H - 0.5 * P * P.transpose();
  add_gram(H, -0.5, P);
  EXPECT_LT((H - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
  EXPECT_TRUE(H == H.transpose());
  // L's strict upper triangle holds M's entries: unread.
  const Eigen::MatrixXd lower = M.triangularView<Eigen::Lower>();
  const Eigen::MatrixXd G = triangular_gram(M);
  const Eigen::MatrixXd LLt = lower * lower.transpose();
  EXPECT_LT((G - LLt).cwiseAbs().maxCoeff(), 1e-13 * LLt.cwiseAbs().maxCoeff());
  EXPECT_TRUE(G == G.transpose());
  // S's strict upper triangle unread: only S's lower triangle mirrored is multiplied.
  const Eigen::MatrixXd S = lower + lower.transpose();
  Eigen::MatrixXd upper_garbage = S;
  upper_garbage.triangularView<Eigen::StrictlyUpper>().setConstant(1e30);
  const Eigen::MatrixXd Y = symmetric_product(upper_garbage, P);
  const Eigen::MatrixXd SP = S * P;
  EXPECT_LT((Y - SP).cwiseAbs().maxCoeff(), 1e-13 * SP.cwiseAbs().maxCoeff());
}

} // namespace
} // namespace sig
