// The split CHOLMOD solve (cholmod_split.hpp).
#include "solver/cholmod_split.hpp"

#include "cholmod_view.hpp"
#include "core/error.hpp"
#include "solver/dense_cholesky.hpp"
#include "solver/linear_solver.hpp"

#include <cholmod.h>

#include <algorithm>
#include <cmath>

namespace sig {

struct CholmodSplitSolver::State {
  CholmodFactor f;       ///< its b: the last forward substitution
  std::vector<int> perm; ///< P: row k of P K P^T is row perm[k] of K
  int n = 0, m = 0;
  bool reduced = false;
  SplitLayout layout = SplitLayout::simplicial;
  Eigen::MatrixXd L_cc; ///< supernodal: the trailing block, which stays in the factor
};

namespace {

/// CSYMAMD's constraint sets on the whole K: 0 the interior, 1 the Schur variables (ordered
/// after set 0), whose factor is sparser on 2D meshes than a free order of the interior (METIS)
/// followed by the Schur variables (the interior's order knows nothing of them). Fills perm.
void order_constrained(cholmod_sparse& view, const std::vector<int>& is_last,
                       const std::vector<int>& last, std::vector<int>& perm, cholmod_common& c) {
  std::vector<int> order(view.nrow);
  SIG_VERIFY(cholmod_csymamd(&view, const_cast<int*>(is_last.data()), order.data(), &c),
             "CHOLMOD split: CSYMAMD ordering failed: status " << c.status);
  for (int d : order)
    if (!is_last[d]) perm.push_back(d);
  perm.insert(perm.end(), last.begin(), last.end());
}

/// Nested dissection of K_ii alone (METIS, postordered; AMD where CHOLMOD has no METIS), the
/// Schur variables appended: they are the root of the elimination tree, as MUMPS's are.
void order_interior(const Eigen::SparseMatrix<double>& K, const std::vector<int>& is_last,
                    const std::vector<int>& last, std::vector<int>& perm, cholmod_common& c) {
  const int n = static_cast<int>(K.rows());
  std::vector<int> interior, position(n, -1);
  for (int d = 0; d < n; ++d)
    if (!is_last[d]) {
      position[d] = static_cast<int>(interior.size());
      interior.push_back(d);
    }
  std::vector<Eigen::Triplet<double>> lower;
  for (int j = 0; j < n; ++j)
    if (position[j] >= 0)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
        if (it.row() >= j && position[it.row()] >= 0)
          lower.emplace_back(position[it.row()], position[j], it.value());
  const int ni = static_cast<int>(interior.size());
  Eigen::SparseMatrix<double> K_ii(ni, ni);
  K_ii.setFromTriplets(lower.begin(), lower.end());
  cholmod_sparse view = view_lower(K_ii);
  std::vector<int> order(ni);
  if (!cholmod_metis(&view, nullptr, 0, 1, order.data(), &c)) {
    SIG_VERIFY(c.status == CHOLMOD_NOT_INSTALLED || c.status == CHOLMOD_INVALID,
               "CHOLMOD split: METIS ordering failed: status " << c.status);
    c.status = CHOLMOD_OK;
    SIG_VERIFY(cholmod_amd(&view, nullptr, 0, order.data(), &c),
               "CHOLMOD split: AMD ordering failed: status " << c.status);
  }
  for (int k : order)
    perm.push_back(interior[k]);
  perm.insert(perm.end(), last.begin(), last.end());
}

/// The trailing m x m block of a supernodal factor (the columns and rows from n - m on).
Eigen::MatrixXd trailing_block(const cholmod_factor& L, int m) {
  const int n = static_cast<int>(L.n), ni = n - m;
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  const auto* rows = static_cast<const int*>(L.s);
  const auto* x = static_cast<const double*>(L.x);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(m, m);
  for (size_t s = 0; s < L.nsuper; ++s) {
    const int k1 = std::max(super[s], ni), k2 = super[s + 1];
    const int nsrow = pi[s + 1] - pi[s];
    for (int k = k1; k < k2; ++k)
      for (int q = k - super[s]; q < nsrow; ++q) // the rows of column k from its diagonal on
        block(rows[pi[s] + q] - ni, k - ni) = x[px[s] + (k - super[s]) * nsrow + q];
  }
  return block;
}

} // namespace

CholmodSplitSolver::CholmodSplitSolver(const Eigen::SparseMatrix<double>& K,
                                       const std::vector<int>& last, SplitLayout layout)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.n = static_cast<int>(K.rows());
  s.m = static_cast<int>(last.size());
  s.layout = layout;
  SIG_VERIFY(K.rows() == K.cols() && K.isCompressed(),
             "CHOLMOD split: K must be square, compressed");
  SIG_VERIFY(s.m > 0 && s.m < s.n && std::is_sorted(last.begin(), last.end()) &&
                 std::adjacent_find(last.begin(), last.end()) == last.end() && last.front() >= 0 &&
                 last.back() < s.n,
             "CHOLMOD split: the Schur variables must be sorted, distinct and in [0, n)");
  std::vector<int> is_last(s.n, 0);
  for (int d : last)
    is_last[d] = 1;
  const int ni = s.n - s.m;
  const bool supernodal = layout == SplitLayout::supernodal;

  // 1. The order, the Schur variables last.
  cholmod_common& c = s.f.c;
  cholmod_sparse view = view_lower(K);
  if (supernodal)
    order_interior(K, is_last, last, s.perm, c);
  else
    order_constrained(view, is_last, last, s.perm, c);

  // 2. The whole K in that order (supernodal: K_cc shifted by sigma); no postorder, so the Schur
  //    variables stay last (the supernodal interior order is postordered already).
  double sigma = 0;
  Eigen::SparseMatrix<double> shifted;
  if (supernodal) {
    for (int d : last)
      sigma = std::max(sigma, std::abs(K.coeff(d, d)));
    SIG_VERIFY(sigma > 0, "CHOLMOD split: the Schur variables' diagonal of K is zero");
    shifted = K;
    for (int d : last)
      shifted.coeffRef(d, d) += sigma;
    shifted.makeCompressed(); // a diagonal entry missing from K's pattern was inserted
    view = view_lower(shifted);
  }
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.postorder = 0;
  c.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  c.final_ll = 1;
  s.f.L = cholmod_analyze_p(&view, s.perm.data(), nullptr, 0, &c);
  SIG_VERIFY(s.f.L, "CHOLMOD split: analysis failed: status " << c.status);
  const int* used = static_cast<const int*>(s.f.L->Perm);
  SIG_VERIFY(std::equal(s.perm.begin(), s.perm.end(), used),
             "CHOLMOD split: the factor's order is not the given one");
  cholmod_factorize(&view, s.f.L, &c);
  if (c.status != CHOLMOD_OK || s.f.L->minor != static_cast<size_t>(s.n))
    throw FactorizationFailure(std::string("CHOLMOD split: ") + (supernodal ? "K_ii" : "K") +
                               " is not positive definite (status " + std::to_string(c.status) +
                               ", minor " + std::to_string(s.f.L->minor) + ")");
  SIG_VERIFY(bool(s.f.L->is_super) == supernodal && s.f.L->is_ll,
             "CHOLMOD split: not the LL^T factor asked for");

  // 3. The trailing block L_cc, and S = L_cc L_cc^T (- sigma I).
  if (supernodal) {
    s.L_cc = trailing_block(*s.f.L, s.m);
    S_ = triangular_gram(s.L_cc);
    S_.diagonal().array() -= sigma;
  } else {
    // L_cc is made the identity in the factor (its columns cut to their diagonal 1), so the
    // substitutions skip it: the forward one leaves z_c = b_c - L_ci z_i, the condensed load
    // L_cc z_c itself, and the backward one takes x_c as it is.
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
  }
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
  const Eigen::Map<const Eigen::VectorXd> z_c(s.f.values() + (s.n - s.m), s.m);
  if (s.layout == SplitLayout::supernodal) return s.L_cc.triangularView<Eigen::Lower>() * z_c;
  return z_c;
}

Eigen::VectorXd CholmodSplitSolver::expand(const Eigen::VectorXd& x_c) {
  State& s = *state_;
  SIG_VERIFY(s.reduced && x_c.size() == s.m,
             "CHOLMOD split: expand needs a reduce() before it and " << s.m << " values");
  Eigen::Map<Eigen::VectorXd> z_c(s.f.values() + (s.n - s.m), s.m);
  if (s.layout == SplitLayout::supernodal)
    z_c = s.L_cc.triangularView<Eigen::Lower>().transpose() * x_c;
  else
    z_c = x_c;
  s.f.solve(CHOLMOD_Lt);
  s.reduced = false;
  const double* z = s.f.values();
  Eigen::VectorXd u(s.n);
  for (int k = 0; k < s.n; ++k)
    u[s.perm[k]] = z[k];
  for (int k = 0; k < s.m; ++k) // exactly x_c, whatever the round trip through L_cc
    u[s.perm[s.n - s.m + k]] = x_c[k];
  return u;
}

} // namespace sig
