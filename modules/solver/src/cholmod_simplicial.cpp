// The simplicial CHOLMOD solve (cholmod_simplicial.hpp).
#include "solver/cholmod_simplicial.hpp"

#include "cholmod_view.hpp"
#include "core/error.hpp"

#include <cholmod.h>

#include <algorithm>

namespace sig {

struct CholmodSimplicialSolver::State {
  cholmod_common c{};
  cholmod_factor* L = nullptr;
  cholmod_dense* b = nullptr; ///< the right side, n x 1
  cholmod_dense* y = nullptr; ///< solve2's workspace
  cholmod_dense* e = nullptr;
  State() {
    cholmod_start(&c);
    c.print = 0;
  }
  ~State() {
    cholmod_free_dense(&b, &c);
    cholmod_free_dense(&y, &c);
    cholmod_free_dense(&e, &c);
    if (L) cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
  }
};

CholmodSimplicialSolver::CholmodSimplicialSolver(const Eigen::SparseMatrix<double>& A)
    : state_(std::make_unique<State>()) {
  SIG_VERIFY(A.rows() == A.cols() && A.isCompressed(),
             "CHOLMOD simplicial: the matrix must be square, compressed");
  State& s = *state_;
  cholmod_common& c = s.c;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_METIS;
  c.postorder = 1;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.final_ll = 1;
  cholmod_sparse view = view_lower(A);
  s.L = cholmod_analyze(&view, &c);
  if (!s.L) {
    c.method[0].ordering = CHOLMOD_AMD;
    s.L = cholmod_analyze(&view, &c);
  }
  SIG_VERIFY(s.L, "CHOLMOD simplicial: analysis failed: status " << c.status);
  cholmod_factorize(&view, s.L, &c);
  SIG_VERIFY(c.status == CHOLMOD_OK && s.L->minor == s.L->n,
             "CHOLMOD simplicial: the matrix is not positive definite (status " << c.status << ")");
  s.b = cholmod_allocate_dense(s.L->n, 1, s.L->n, CHOLMOD_REAL, &c);
  SIG_VERIFY(s.b, "CHOLMOD simplicial: out of memory");
}

CholmodSimplicialSolver::~CholmodSimplicialSolver() = default;

Eigen::VectorXd CholmodSimplicialSolver::solve(const Eigen::VectorXd& b) {
  State& s = *state_;
  const auto n = static_cast<Eigen::Index>(s.L->n);
  SIG_VERIFY(b.size() == n,
             "CHOLMOD simplicial: a right side of size " << b.size() << " for " << n);
  std::copy_n(b.data(), n, static_cast<double*>(s.b->x));
  cholmod_dense* x = nullptr;
  const int ok = cholmod_solve2(CHOLMOD_A, s.L, s.b, nullptr, &x, nullptr, &s.y, &s.e, &s.c);
  SIG_VERIFY(ok && x, "CHOLMOD simplicial: solve failed: status " << s.c.status);
  Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), n);
  cholmod_free_dense(&x, &s.c);
  return u;
}

} // namespace sig
