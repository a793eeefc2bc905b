#include "solver/dense_cholesky.hpp"

extern "C" void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);

namespace sig {

bool cholesky_in_place(Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  if (n == 0) return true;
  const int lda = static_cast<int>(A.outerStride());
  int info = 0;
  dpotrf_("L", &n, A.data(), &lda, &info);
  return info == 0;
}

} // namespace sig
