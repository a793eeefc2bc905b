#include "solver/symmetric_product.hpp"

#include "solver/mpi_session.hpp"

namespace sig {

SymmetricProduct::SymmetricProduct(const Eigen::SparseMatrix<double>& A, bool rank_rows)
    : rank_rows_(rank_rows) {
  // A rank's rows are not symmetric: their lower triangle would drop the entries right of the
  // diagonal that no other rank gives.
  if (rank_rows_)
    stored_ = A;
  else
    stored_ = A.triangularView<Eigen::Lower>();
}

Eigen::VectorXd SymmetricProduct::operator()(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y;
  if (!rank_rows_) {
    y.noalias() = stored_.selfadjointView<Eigen::Lower>() * x;
    return y;
  }
  y.noalias() = stored_ * x;
  mpi::sum(y.data(), static_cast<int>(y.size()));
  return y;
}

void SymmetricProduct::subtract(const Eigen::VectorXd& x, Eigen::VectorXd& b) const {
  if (rank_rows_)
    b -= (*this)(x);
  else
    b.noalias() -= stored_.selfadjointView<Eigen::Lower>() * x;
}

} // namespace sig
