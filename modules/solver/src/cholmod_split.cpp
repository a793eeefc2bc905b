// The split CHOLMOD solve (cholmod_split.hpp).
#include "solver/cholmod_split.hpp"

#include "cholmod_view.hpp"
#include "core/error.hpp"
#include "solver/linear_solver.hpp"

#include <cholmod.h>

#include <algorithm>

namespace sig {

struct CholmodSplitSolver::State {
  CholmodFactor f;       ///< its b: the last forward substitution
  std::vector<int> perm; ///< P: row k of P K P^T is row perm[k] of K
  int n = 0, m = 0;
  bool reduced = false;
};

CholmodSplitSolver::CholmodSplitSolver(const Eigen::SparseMatrix<double>& K,
                                       const std::vector<int>& last)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.n = static_cast<int>(K.rows());
  s.m = static_cast<int>(last.size());
  SIG_VERIFY(K.rows() == K.cols() && K.isCompressed(),
             "CHOLMOD split: K must be square, compressed");
  SIG_VERIFY(s.m > 0 && s.m < s.n && std::is_sorted(last.begin(), last.end()) &&
                 std::adjacent_find(last.begin(), last.end()) == last.end() && last.front() >= 0 &&
                 last.back() < s.n,
             "CHOLMOD split: the Schur variables must be sorted, distinct and in [0, n)");
  // CSYMAMD's constraint sets: 0 the interior, 1 the Schur variables (ordered after set 0).
  std::vector<int> is_last(s.n, 0);
  for (int d : last)
    is_last[d] = 1;
  const int ni = s.n - s.m;

  // 1. A fill-reducing order constrained to put the Schur variables last: CSYMAMD on the whole
  //    K with two constraint sets, whose factor is sparser than a free order of the interior
  //    (METIS) followed by the Schur variables (the interior's order knows nothing of them).
  cholmod_common& c = s.f.c;
  std::vector<int> order(s.n);
  cholmod_sparse view = view_lower(K);
  SIG_VERIFY(cholmod_csymamd(&view, is_last.data(), order.data(), &c),
             "CHOLMOD split: CSYMAMD ordering failed: status " << c.status);
  for (int d : order)
    if (!is_last[d]) s.perm.push_back(d);
  s.perm.insert(s.perm.end(), last.begin(), last.end());

  // 2. The whole K in that order, simplicial LL^T (its substitutions cost about half the
  //    supernodal ones on these 2D meshes: drivers/bench-scene5.sh); no postorder, so the Schur
  //    variables stay last.
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.postorder = 0;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.final_ll = 1;
  s.f.L = cholmod_analyze_p(&view, s.perm.data(), nullptr, 0, &c);
  SIG_VERIFY(s.f.L, "CHOLMOD split: analysis failed: status " << c.status);
  const int* used = static_cast<const int*>(s.f.L->Perm);
  SIG_VERIFY(std::equal(s.perm.begin(), s.perm.end(), used),
             "CHOLMOD split: the factor's order is not the given one");
  cholmod_factorize(&view, s.f.L, &c);
  if (c.status != CHOLMOD_OK || s.f.L->minor != static_cast<size_t>(s.n))
    throw FactorizationFailure("CHOLMOD split: K is not positive definite (status " +
                               std::to_string(c.status) + ", minor " +
                               std::to_string(s.f.L->minor) + ")");
  SIG_VERIFY(!s.f.L->is_super && s.f.L->is_ll, "CHOLMOD split: expected a simplicial LL^T");

  // 3. The trailing block L_cc, and S = L_cc L_cc^T. Then L_cc is made the identity in the
  //    factor (its columns cut to their diagonal 1), so the substitutions skip it: the forward
  //    one leaves z_c = b_c - L_ci z_i, the condensed load L_cc z_c itself, and the backward one
  //    takes x_c as it is.
  auto* Lp = static_cast<const int*>(s.f.L->p);
  auto* Li = static_cast<const int*>(s.f.L->i);
  auto* Lnz = static_cast<int*>(s.f.L->nz);
  auto* Lx = static_cast<double*>(s.f.L->x);
  Eigen::MatrixXd L_cc = Eigen::MatrixXd::Zero(s.m, s.m);
  for (int j = ni; j < s.n; ++j) {
    for (int q = Lp[j]; q < Lp[j] + Lnz[j]; ++q)
      L_cc(Li[q] - ni, j - ni) = Lx[q];
    SIG_VERIFY(Li[Lp[j]] == j, "CHOLMOD split: a column's diagonal is not its first entry");
    Lx[Lp[j]] = 1;
    Lnz[j] = 1;
  }
  S_ = L_cc.triangularView<Eigen::Lower>() * L_cc.transpose();
  S_ = 0.5 * (S_ + S_.transpose()).eval();
  s.f.allocate();
}

CholmodSplitSolver::~CholmodSplitSolver() = default;

Eigen::VectorXd CholmodSplitSolver::reduce(const Eigen::VectorXd& b) {
  State& s = *state_;
  SIG_VERIFY(b.size() == s.n, "CHOLMOD split: a load of size " << b.size() << " for " << s.n);
  double* z = s.f.values();
  for (int k = 0; k < s.n; ++k)
    z[k] = b[s.perm[k]];
  s.f.solve(CHOLMOD_L);
  s.reduced = true;
  return Eigen::Map<const Eigen::VectorXd>(s.f.values() + (s.n - s.m), s.m);
}

Eigen::VectorXd CholmodSplitSolver::expand(const Eigen::VectorXd& x_c) {
  State& s = *state_;
  SIG_VERIFY(s.reduced && x_c.size() == s.m,
             "CHOLMOD split: expand needs a reduce() before it and " << s.m << " values");
  Eigen::Map<Eigen::VectorXd>(s.f.values() + (s.n - s.m), s.m) = x_c;
  s.f.solve(CHOLMOD_Lt);
  s.reduced = false;
  const double* z = s.f.values();
  Eigen::VectorXd u(s.n);
  for (int k = 0; k < s.n; ++k)
    u[s.perm[k]] = z[k];
  return u;
}

} // namespace sig
