// The products of a march's right side (solver/symmetric_product.hpp): from the lower triangle in
// one process, from a rank's rows under mpirun. A plain process is a job of one rank whose rows
// are the whole matrix (the sum over the ranks then leaves them as they are): both forms give
// A x, and subtract() gives b - A x.
#include "solver/symmetric_product.hpp"

#include "solver/mpi_session.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace sig {
namespace {

Eigen::SparseMatrix<double> random_symmetric(int n, std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 4.0 + value(random));
    for (int j : {i + 1, i + 3})
      if (j < n) {
        const double a = value(random);
        entries.emplace_back(i, j, a);
        entries.emplace_back(j, i, a);
      }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

TEST(SymmetricProduct, LowerTriangleAndRankRowsBothGiveTheProduct) {
  std::mt19937 random(7);
  const int n = 40;
  const Eigen::SparseMatrix<double> A = random_symmetric(n, random);
  const Eigen::VectorXd x = Eigen::VectorXd::Random(n), b = Eigen::VectorXd::Random(n);
  const Eigen::VectorXd expected = A * x;
  mpi::start(); // a singleton: the rank rows' sum is a collective call
  for (const bool rank_rows : {false, true}) {
    const SymmetricProduct product(A, rank_rows);
    EXPECT_LT((product(x) - expected).norm(), 1e-14 * expected.norm()) << rank_rows;
    Eigen::VectorXd c = b;
    product.subtract(x, c);
    EXPECT_LT((c - (b - expected)).norm(), 1e-14 * expected.norm()) << rank_rows;
  }
}

// The lower triangle alone carries the product: an upper triangle edited away changes nothing
// in one process, and a rank's rows must keep theirs (they are not symmetric).
TEST(SymmetricProduct, OneProcessReadsTheLowerTriangleOnly) {
  std::mt19937 random(11);
  const int n = 12;
  const Eigen::SparseMatrix<double> A = random_symmetric(n, random);
  const Eigen::SparseMatrix<double> lower = A.triangularView<Eigen::Lower>();
  const Eigen::VectorXd x = Eigen::VectorXd::Random(n);
  mpi::start();
  EXPECT_LT((SymmetricProduct(lower, false)(x) - A * x).norm(), 1e-14 * (A * x).norm());
  EXPECT_GT((SymmetricProduct(lower, true)(x) - A * x).norm(), 1e-3);
}

} // namespace
} // namespace sig
