#include "solver/cholmod_solver.hpp"

#include "core/error.hpp"

#include "cholmod_view.hpp"

#include <cholmod.h>

namespace sig {

namespace {

std::string status_text(int status) {
  switch (status) {
  case CHOLMOD_OK:
    return "ok";
  case CHOLMOD_NOT_INSTALLED:
    return "method not installed";
  case CHOLMOD_OUT_OF_MEMORY:
    return "out of memory";
  case CHOLMOD_TOO_LARGE:
    return "integer overflow";
  case CHOLMOD_INVALID:
    return "invalid input";
  case CHOLMOD_NOT_POSDEF:
    return "not positive definite";
  case CHOLMOD_DSMALL:
    return "tiny diagonal entry";
  default:
    return "unknown status";
  }
}

/// CHOLMOD reads the compressed arrays directly; an uncompressed matrix is copied once.
const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& A,
                                              Eigen::SparseMatrix<double>& copy) {
  if (A.isCompressed()) return A;
  copy = A;
  copy.makeCompressed();
  return copy;
}

/// cholmod_common set up for our use: errors come back as exceptions, not printed.
struct Common {
  cholmod_common c{};
  Common() {
    cholmod_start(&c);
    c.print = 0;
  }
  ~Common() { cholmod_finish(&c); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
};

} // namespace

struct CholmodSolver::State {
  Common common;
  cholmod_factor* L = nullptr;
  std::uint64_t pattern = 0; ///< fingerprint of the pattern L was analyzed for
  bool factorized = false;
  ~State() {
    if (L) cholmod_free_factor(&L, &common.c);
  }
};

CholmodSolver::CholmodSolver() : state_(std::make_unique<State>()) {}
CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const Eigen::SparseMatrix<double>& A) {
  SIG_VERIFY(A.rows() == A.cols(),
             "CHOLMOD: matrix is " << A.rows() << " x " << A.cols() << ", not square");
  State& s = *state_;
  if (s.L) cholmod_free_factor(&s.L, &s.common.c);
  s.factorized = false;

  cholmod_common& c = s.common.c;
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.postorder = 1;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_METIS;
  Eigen::SparseMatrix<double> copy;
  cholmod_sparse view = view_lower(compressed(A, copy));
  s.L = cholmod_analyze(&view, &c);
  if (!s.L && (c.status == CHOLMOD_NOT_INSTALLED || c.status == CHOLMOD_INVALID)) {
    // CHOLMOD built without its Partition module: METIS is not there, AMD always is.
    c.method[0].ordering = CHOLMOD_AMD;
    s.L = cholmod_analyze(&view, &c);
  }
  SIG_VERIFY(s.L, "CHOLMOD: symbolic analysis failed: status " << c.status << " ("
                                                               << status_text(c.status) << ")");
  s.pattern = pattern_fingerprint(A);
}

void CholmodSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  State& s = *state_;
  if (!s.L || s.pattern != pattern_fingerprint(A)) analyze(A);
  s.factorized = false;
  cholmod_common& c = s.common.c;
  Eigen::SparseMatrix<double> copy;
  cholmod_sparse view = view_lower(compressed(A, copy));
  const int ok = cholmod_factorize(&view, s.L, &c);
  if (c.status == CHOLMOD_NOT_POSDEF)
    throw FactorizationFailure("CHOLMOD: matrix not positive definite (status " +
                               std::to_string(c.status) + ": leading minor of order " +
                               std::to_string(s.L->minor + 1) + " of " + std::to_string(A.rows()) +
                               " fails)");
  SIG_VERIFY(ok && c.status >= CHOLMOD_OK, "CHOLMOD: numeric factorization failed: status "
                                               << c.status << " (" << status_text(c.status) << ")");
  s.factorized = true;
}

Eigen::VectorXd CholmodSolver::solve(const Eigen::VectorXd& b) const {
  return solve(Eigen::MatrixXd(b)).col(0);
}

Eigen::MatrixXd CholmodSolver::solve(const Eigen::MatrixXd& B) const {
  const State& s = *state_;
  SIG_VERIFY(s.factorized, "CHOLMOD: solve before a successful factorize");
  SIG_VERIFY(B.rows() == static_cast<long>(s.L->n),
             "CHOLMOD: right side has " << B.rows() << " rows, matrix " << s.L->n);
  Eigen::MatrixXd rhs = B; // CHOLMOD takes a non-const pointer
  cholmod_dense b{};
  b.nrow = static_cast<size_t>(rhs.rows());
  b.ncol = static_cast<size_t>(rhs.cols());
  b.nzmax = b.nrow * b.ncol;
  b.d = b.nrow;
  b.x = rhs.data();
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  // A private workspace per call keeps solve() const and reentrant: the factor is only read.
  Common local;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, s.L, &b, &local.c);
  SIG_VERIFY(x, "CHOLMOD: solve failed: status " << local.c.status << " ("
                                                 << status_text(local.c.status) << ")");
  Eigen::MatrixXd X =
      Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), rhs.rows(), rhs.cols());
  cholmod_free_dense(&x, &local.c);
  return X;
}

std::string CholmodSolver::ordering() const {
  if (!state_->L) return "";
  switch (state_->L->ordering) {
  case CHOLMOD_METIS:
    return "metis";
  case CHOLMOD_AMD:
    return "amd";
  case CHOLMOD_NATURAL:
    return "natural";
  default:
    return "other";
  }
}

} // namespace sig
