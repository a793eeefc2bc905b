#include "solver/dense_cholesky.hpp"

#include "core/error.hpp"

#include <cblas.h>

#include <limits>

extern "C" void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
extern "C" void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);
extern "C" void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv,
                        int* info);
extern "C" void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a,
                        const int* lda, const int* ipiv, double* b, const int* ldb, int* info);

namespace sig {

void add_gram(Eigen::Ref<Eigen::MatrixXd> H, double alpha,
              const Eigen::Ref<const Eigen::MatrixXd>& P) {
  SIG_VERIFY(H.rows() == H.cols() && P.rows() == H.rows(),
             "add_gram: H is " << H.rows() << " x " << H.cols() << ", P has " << P.rows()
                               << " rows");
  const int n = static_cast<int>(H.rows()), k = static_cast<int>(P.cols());
  if (n == 0) return;
  if (k > 0)
    cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, n, k, alpha, P.data(),
                static_cast<int>(P.outerStride()), 1.0, H.data(),
                static_cast<int>(H.outerStride()));
  H.triangularView<Eigen::StrictlyUpper>() = H.transpose();
}

Eigen::MatrixXd symmetric_product(const Eigen::MatrixXd& S, const Eigen::MatrixXd& X) {
  SIG_VERIFY(S.rows() == S.cols() && X.rows() == S.rows(),
             "symmetric_product: S is " << S.rows() << " x " << S.cols() << ", X has " << X.rows()
                                        << " rows");
  Eigen::MatrixXd Y(X.rows(), X.cols());
  if (Y.size() == 0) return Y;
  const int n = static_cast<int>(S.rows()), k = static_cast<int>(X.cols());
  cblas_dsymm(CblasColMajor, CblasLeft, CblasLower, n, k, 1.0, S.data(), n, X.data(), n, 0.0,
              Y.data(), n);
  return Y;
}

Eigen::MatrixXd triangular_gram(const Eigen::Ref<const Eigen::MatrixXd>& L) {
  SIG_VERIFY(L.rows() == L.cols(), "triangular_gram: L is " << L.rows() << " x " << L.cols());
  const int n = static_cast<int>(L.rows());
  if (n == 0) return {};
  // With J the reversal, U = J L J is upper triangular and U U^T = J (L L^T) J.
  Eigen::MatrixXd U = L.reverse();
  int info = 0;
  dlauum_("U", &n, U.data(), &n, &info);
  SIG_VERIFY(info == 0, "dlauum failed: info " << info);
  Eigen::MatrixXd G = U.reverse();
  G.triangularView<Eigen::StrictlyUpper>() = G.transpose();
  return G;
}

bool cholesky_in_place(Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  if (n == 0) return true;
  const int lda = static_cast<int>(A.outerStride());
  int info = 0;
  dpotrf_("L", &n, A.data(), &lda, &info);
  return info == 0;
}

void DenseLu::compute(const RowMatrixXd& A, bool lapack) {
  lapack_ = lapack;
  if (!lapack_) {
    small_.compute(A);
    return;
  }
  // The row-major A is A^T column-major: dgetrf factors A^T, solve() takes the transpose.
  factors_ = Eigen::Map<const Eigen::MatrixXd>(A.data(), A.cols(), A.rows());
  const int n = static_cast<int>(A.rows());
  pivots_.resize(static_cast<size_t>(n));
  int info = 0;
  dgetrf_(&n, &n, factors_.data(), &n, pivots_.data(), &info);
  singular_ = info != 0;
}

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  if (!lapack_) return small_.solve(b);
  Eigen::VectorXd x = b;
  if (singular_) return x.setConstant(std::numeric_limits<double>::quiet_NaN());
  const int n = static_cast<int>(x.size()), one = 1;
  int info = 0;
  dgetrs_("T", &n, &one, factors_.data(), &n, pivots_.data(), x.data(), &n, &info);
  return x;
}

} // namespace sig
