// The split CHOLMOD solve (cholmod_split.hpp).
#include "solver/cholmod_split.hpp"

#include "cholmod_view.hpp"
#include "core/error.hpp"

#include <cholmod.h>

#include <algorithm>

namespace sig {

struct CholmodSplitSolver::State {
  cholmod_common c{};
  cholmod_factor* L = nullptr;
  std::vector<int> perm; ///< P: row k of P K P^T is row perm[k] of K
  int n = 0, m = 0;
  cholmod_dense* z = nullptr; ///< the last forward substitution, n x 1
  cholmod_dense* y = nullptr; ///< solve2's workspace
  cholmod_dense* e = nullptr;
  bool reduced = false;

  State() {
    cholmod_start(&c);
    c.print = 0;
  }
  ~State() {
    cholmod_free_dense(&z, &c);
    cholmod_free_dense(&y, &c);
    cholmod_free_dense(&e, &c);
    if (L) cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
  }
  /// x := L^-1 x (sys CHOLMOD_L) or L^-T x (CHOLMOD_Lt) in place of z, reusing the workspace.
  void substitute(int sys, cholmod_dense* b) {
    cholmod_dense* x = nullptr;
    const int ok = cholmod_solve2(sys, L, b, nullptr, &x, nullptr, &y, &e, &c);
    SIG_VERIFY(ok && x, "CHOLMOD: substitution failed: status " << c.status);
    std::copy_n(static_cast<double*>(x->x), n, static_cast<double*>(z->x));
    cholmod_free_dense(&x, &c);
  }
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
  std::vector<char> is_last(s.n, 0);
  for (int d : last)
    is_last[d] = 1;
  std::vector<int> interior;
  for (int d = 0; d < s.n; ++d)
    if (!is_last[d]) interior.push_back(d);
  const int ni = s.n - s.m;

  // 1. A fill-reducing order of the interior (METIS, AMD without it), then the Schur variables.
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<int> position(s.n, -1);
  for (int k = 0; k < ni; ++k)
    position[interior[k]] = k;
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      if (position[it.row()] >= 0 && position[j] >= 0)
        entries.emplace_back(position[it.row()], position[j], it.value());
  Eigen::SparseMatrix<double> K_ii(ni, ni);
  K_ii.setFromTriplets(entries.begin(), entries.end());
  K_ii.makeCompressed();
  cholmod_common& c = s.c;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_METIS;
  c.postorder = 1;
  cholmod_sparse view = view_lower(K_ii);
  cholmod_factor* symbolic = cholmod_analyze(&view, &c);
  if (!symbolic) {
    c.method[0].ordering = CHOLMOD_AMD;
    symbolic = cholmod_analyze(&view, &c);
  }
  SIG_VERIFY(symbolic, "CHOLMOD split: analysis of the interior failed: status " << c.status);
  const int* interior_perm = static_cast<const int*>(symbolic->Perm);
  for (int k = 0; k < ni; ++k)
    s.perm.push_back(interior[interior_perm[k]]);
  cholmod_free_factor(&symbolic, &c);
  s.perm.insert(s.perm.end(), last.begin(), last.end());

  // 2. The whole K in that order, supernodal LL^T; no postorder, so the Schur variables stay last.
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.postorder = 0;
  c.supernodal = CHOLMOD_SUPERNODAL;
  view = view_lower(K);
  s.L = cholmod_analyze_p(&view, s.perm.data(), nullptr, 0, &c);
  SIG_VERIFY(s.L, "CHOLMOD split: analysis failed: status " << c.status);
  const int* used = static_cast<const int*>(s.L->Perm);
  SIG_VERIFY(std::equal(s.perm.begin(), s.perm.end(), used),
             "CHOLMOD split: the factor's order is not the given one");
  cholmod_factorize(&view, s.L, &c);
  SIG_VERIFY(c.status == CHOLMOD_OK && s.L->minor == static_cast<size_t>(s.n),
             "CHOLMOD split: K is not positive definite (status " << c.status << ", minor "
                                                                  << s.L->minor << ")");
  SIG_VERIFY(s.L->is_super && s.L->is_ll, "CHOLMOD split: expected a supernodal LL^T");

  // 3. The trailing block L_cc of the supernodal factor, and S = L_cc L_cc^T.
  L_cc_ = Eigen::MatrixXd::Zero(s.m, s.m);
  const auto* super = static_cast<const int*>(s.L->super);
  const auto* pi = static_cast<const int*>(s.L->pi);
  const auto* px = static_cast<const int*>(s.L->px);
  const auto* rows = static_cast<const int*>(s.L->s);
  const auto* x = static_cast<const double*>(s.L->x);
  for (size_t k = 0; k < s.L->nsuper; ++k) {
    const int k1 = super[k], k2 = super[k + 1], nrows = pi[k + 1] - pi[k];
    for (int j = std::max(k1, ni); j < k2; ++j)
      for (int r = j - k1; r < nrows; ++r)
        L_cc_(rows[pi[k] + r] - ni, j - ni) = x[px[k] + r + (j - k1) * nrows];
  }
  S_ = L_cc_.triangularView<Eigen::Lower>() * L_cc_.transpose();
  S_ = 0.5 * (S_ + S_.transpose()).eval();
  s.z = cholmod_allocate_dense(s.n, 1, s.n, CHOLMOD_REAL, &c);
  SIG_VERIFY(s.z, "CHOLMOD split: out of memory");
}

CholmodSplitSolver::~CholmodSplitSolver() = default;

Eigen::VectorXd CholmodSplitSolver::reduce(const Eigen::VectorXd& b) {
  State& s = *state_;
  SIG_VERIFY(b.size() == s.n, "CHOLMOD split: a load of size " << b.size() << " for " << s.n);
  auto* z = static_cast<double*>(s.z->x);
  for (int k = 0; k < s.n; ++k)
    z[k] = b[s.perm[k]];
  s.substitute(CHOLMOD_L, s.z);
  s.reduced = true;
  const Eigen::Map<const Eigen::VectorXd> z_c(z + (s.n - s.m), s.m);
  return L_cc_.triangularView<Eigen::Lower>() * z_c;
}

Eigen::VectorXd CholmodSplitSolver::expand(const Eigen::VectorXd& x_c) {
  State& s = *state_;
  SIG_VERIFY(s.reduced && x_c.size() == s.m,
             "CHOLMOD split: expand needs a reduce() before it and " << s.m << " values");
  auto* z = static_cast<double*>(s.z->x);
  Eigen::Map<Eigen::VectorXd>(z + (s.n - s.m), s.m) =
      L_cc_.triangularView<Eigen::Lower>().transpose() * x_c;
  s.substitute(CHOLMOD_Lt, s.z);
  s.reduced = false;
  Eigen::VectorXd u(s.n);
  for (int k = 0; k < s.n; ++k)
    u[s.perm[k]] = z[k];
  for (int k = 0; k < s.m; ++k)
    u[s.perm[s.n - s.m + k]] = x_c[k];
  return u;
}

} // namespace sig
