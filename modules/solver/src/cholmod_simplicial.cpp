// The simplicial CHOLMOD solve (cholmod_simplicial.hpp).
#include "solver/cholmod_simplicial.hpp"

#include "cholmod_view.hpp"
#include "core/error.hpp"
#include "solver/linear_solver.hpp"

#include <cholmod.h>

#include <algorithm>

namespace sig {

struct CholmodSimplicialSolver::State : CholmodFactor {};

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
  if (c.status != CHOLMOD_OK || s.L->minor != s.L->n)
    throw FactorizationFailure("CHOLMOD simplicial: the matrix is not positive definite (status " +
                               std::to_string(c.status) + ")");
  s.allocate();
}

CholmodSimplicialSolver::~CholmodSimplicialSolver() = default;

Eigen::VectorXd CholmodSimplicialSolver::solve(const Eigen::VectorXd& b) {
  State& s = *state_;
  const auto n = static_cast<Eigen::Index>(s.L->n);
  SIG_VERIFY(b.size() == n,
             "CHOLMOD simplicial: a right side of size " << b.size() << " for " << n);
  std::copy_n(b.data(), n, s.values());
  s.solve(CHOLMOD_A);
  return Eigen::Map<const Eigen::VectorXd>(s.values(), n);
}

} // namespace sig
