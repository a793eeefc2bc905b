#pragma once
// y = A x for a symmetric sparse A that a march multiplies every step (K u, M w, the memory
// terms' K_m h). In one process only A's lower triangle is stored and multiplied through its
// self-adjoint view: half the memory traffic of the whole matrix. A rank of an mpirun job holds
// only the rows of its nodes (the other rows empty, assembly/system.hpp's rank_rows): it
// multiplies those rows and the ranks sum their parts (MPI_Allreduce,
// solver/mpi_session.hpp), so that every rank gets the whole y.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sig {

class SymmetricProduct {
public:
  SymmetricProduct() = default;
  /// `rank_rows`: A holds this rank's rows of an mpirun job, the others empty.
  SymmetricProduct(const Eigen::SparseMatrix<double>& A, bool rank_rows);
  /// A x; with rank rows a collective call of every rank.
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const;
  /// b -= A x, in one process accumulated into b as the product goes (the rounding of a
  /// right side built so).
  void subtract(const Eigen::VectorXd& x, Eigen::VectorXd& b) const;

private:
  Eigen::SparseMatrix<double> stored_; ///< the lower triangle, or this rank's rows
  bool rank_rows_ = false;
};

} // namespace sig
