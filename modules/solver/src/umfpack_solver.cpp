#include "solver/umfpack_solver.hpp"

#include "core/error.hpp"

#include <umfpack.h>

#include <array>

namespace sig {

namespace {

std::string status_text(int status) {
  switch (status) {
  case UMFPACK_OK:
    return "ok";
  case UMFPACK_WARNING_singular_matrix:
    return "singular matrix";
  case UMFPACK_WARNING_determinant_underflow:
    return "determinant underflow";
  case UMFPACK_WARNING_determinant_overflow:
    return "determinant overflow";
  case UMFPACK_ERROR_out_of_memory:
    return "out of memory";
  case UMFPACK_ERROR_invalid_matrix:
    return "invalid matrix";
  case UMFPACK_ERROR_different_pattern:
    return "pattern differs from the analysis";
  case UMFPACK_ERROR_ordering_failed:
    return "ordering failed";
  default:
    return "see umfpack.h";
  }
}

std::string ordering_text(double used) {
  switch (static_cast<int>(used)) {
  case UMFPACK_ORDERING_METIS:
    return "metis";
  case UMFPACK_ORDERING_AMD:
    return "amd";
  case UMFPACK_ORDERING_CHOLMOD:
    return "cholmod";
  case UMFPACK_ORDERING_NONE:
    return "natural";
  default:
    return "other";
  }
}

} // namespace

struct UmfpackSolver::State {
  std::array<double, UMFPACK_CONTROL> control{};
  std::array<double, UMFPACK_INFO> info{};
  void* symbolic = nullptr;
  void* numeric = nullptr;
  /// The factorized matrix: umfpack_di_solve refines the solution iteratively against it.
  Eigen::SparseMatrix<double> A;
  std::uint64_t pattern = 0; ///< fingerprint of the pattern Symbolic was analyzed for
  ~State() { release(); }
  void release_numeric() {
    if (numeric) umfpack_di_free_numeric(&numeric);
  }
  void release() {
    release_numeric();
    if (symbolic) umfpack_di_free_symbolic(&symbolic);
  }
};

UmfpackSolver::UmfpackSolver(MatrixKind kind) : state_(std::make_unique<State>()) {
  State& s = *state_;
  umfpack_di_defaults(s.control.data());
  s.control[UMFPACK_PRL] = 0;
  // UMFPACK falls back to AMD by itself when it was built without METIS.
  s.control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  if (kind != MatrixKind::general) s.control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
}

UmfpackSolver::~UmfpackSolver() = default;

void UmfpackSolver::analyze(const Eigen::SparseMatrix<double>& A) {
  SIG_VERIFY(A.rows() == A.cols(),
             "UMFPACK: matrix is " << A.rows() << " x " << A.cols() << ", not square");
  State& s = *state_;
  s.release();
  s.A = A;
  s.A.makeCompressed();
  const int n = static_cast<int>(A.rows());
  const int status =
      umfpack_di_symbolic(n, n, s.A.outerIndexPtr(), s.A.innerIndexPtr(), s.A.valuePtr(),
                          &s.symbolic, s.control.data(), s.info.data());
  SIG_VERIFY(status == UMFPACK_OK, "UMFPACK: symbolic analysis failed: status "
                                       << status << " (" << status_text(status) << ")");
  s.pattern = pattern_fingerprint(s.A);
}

void UmfpackSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  State& s = *state_;
  if (!s.symbolic || s.pattern != pattern_fingerprint(A))
    analyze(A);
  else {
    s.A = A;
    s.A.makeCompressed();
  }
  s.release_numeric();
  const int status = umfpack_di_numeric(s.A.outerIndexPtr(), s.A.innerIndexPtr(), s.A.valuePtr(),
                                        s.symbolic, &s.numeric, s.control.data(), s.info.data());
  if (status != UMFPACK_OK) {
    // A singular matrix still yields a Numeric object; it must not be used for solves.
    s.release_numeric();
    const std::string what = "UMFPACK: numeric factorization failed: status " +
                             std::to_string(status) + " (" + status_text(status) + ")";
    if (status == UMFPACK_WARNING_singular_matrix)
      throw FactorizationFailure(what + ": the matrix is singular");
    throw Error(what);
  }
}

Eigen::VectorXd UmfpackSolver::solve(const Eigen::VectorXd& b) const {
  const State& s = *state_;
  SIG_VERIFY(s.numeric, "UMFPACK: solve before a successful factorize");
  SIG_VERIFY(b.size() == s.A.rows(),
             "UMFPACK: right side has " << b.size() << " rows, matrix " << s.A.rows());
  Eigen::VectorXd x(b.size());
  // Info is per call so that solve() stays const and reentrant.
  std::array<double, UMFPACK_INFO> info{};
  const int status =
      umfpack_di_solve(UMFPACK_A, s.A.outerIndexPtr(), s.A.innerIndexPtr(), s.A.valuePtr(),
                       x.data(), b.data(), s.numeric, s.control.data(), info.data());
  SIG_VERIFY(status == UMFPACK_OK,
             "UMFPACK: solve failed: status " << status << " (" << status_text(status) << ")");
  return x;
}

std::string UmfpackSolver::ordering() const {
  if (!state_->symbolic) return "";
  return ordering_text(state_->info[UMFPACK_ORDERING_USED]);
}

} // namespace sig
