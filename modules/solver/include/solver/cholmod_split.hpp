#pragma once
// A CHOLMOD LL^T of a symmetric K with a given set of unknowns (the Schur variables) ordered
// last, and a solve split around them: the CHOLMOD counterpart of MUMPS's Schur variables with
// ICNTL(26) (solver/mumps_solver.hpp). With P K P^T = L L^T and L = [L_ii 0; L_ci L_cc]
// (interior first, in a fill-reducing order, then the Schur variables in their order):
//   - the Schur complement is S = K_cc - K_ci K_ii^-1 K_ic = L_cc L_cc^T, the factor's trailing
//     block, read once after the factorization;
//   - reduce(b): the forward substitution with L_ii, z_i = L_ii^-1 (P b)_i, and the condensed
//     load b_c - K_ci K_ii^-1 b_i = (P b)_c - L_ci z_i;
//   - expand(x_c): the backward substitution z_i := L_ii^-T (z_i - L_ci^T x_c), the interior part
//     K_ii^-1 (b_i - K_ic x_c) of the solution whose interface part is x_c.
// So a load costs one forward and one backward substitution, whatever the Schur problem in
// between. Two layouts (SplitLayout):
//   - simplicial: CSYMAMD on the whole K, the Schur variables constrained last; L_cc is then made
//     the identity in the factor, so the substitutions skip it. On the 2D meshes of the
//     quasistatic march its substitutions cost about half the supernodal ones
//     (drivers/bench-scene5.sh). K itself must be positive definite (the whole body held by its
//     Dirichlet conditions): a semi-coercive K, whose rigid modes only the Schur variables hold,
//     is refused (SchurComplement then factorizes K_ii alone).
//   - supernodal: nested dissection (METIS) of K_ii alone, the Schur variables appended, and a
//     supernodal factor: on 3D fill the minimum degree orders and the simplicial factor cost
//     several times the plain factorization (datafiles/scene3d/GETFEM.md). K_cc is shifted by
//     sigma = its largest diagonal entry before the factorization, so that only K_ii need be
//     positive definite (the semi-coercive Hertz ball): L_cc L_cc^T = S + sigma I, and
//     S = L_cc L_cc^T - sigma I (sigma is of the order of S's largest entries: the subtraction
//     loses nothing beyond S's own rounding). L_ci does not depend on the shift, so the
//     substitutions are those above with L_cc kept apart (z_c = L_cc^-1 (...) is multiplied back).
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace sig {

/// The factor's layout and ordering (file comment).
enum class SplitLayout { simplicial, supernodal };

class CholmodSplitSolver {
public:
  /// K: n x n symmetric, stored full (its lower triangle is read); last: the Schur variables,
  /// sorted, distinct, 0 < m < n. FactorizationFailure if K (simplicial) or K_ii (supernodal) is
  /// not positive definite.
  CholmodSplitSolver(const Eigen::SparseMatrix<double>& K, const std::vector<int>& last,
                     SplitLayout layout = SplitLayout::simplicial);
  ~CholmodSplitSolver();
  CholmodSplitSolver(const CholmodSplitSolver&) = delete;
  CholmodSplitSolver& operator=(const CholmodSplitSolver&) = delete;

  /// S = L_cc L_cc^T (m x m, exactly symmetric), rows and columns in the order of `last`.
  const Eigen::MatrixXd& schur_complement() const { return S_; }
  /// The condensed load of b (size n): b_c - K_ci K_ii^-1 b_i, in the order of `last`. The
  /// forward substitution is kept for the next expand().
  Eigen::VectorXd reduce(const Eigen::VectorXd& b);
  /// The solution of K x = b (b of the last reduce()) whose Schur variables are x_c: x_c on them,
  /// K_ii^-1 (b_i - K_ic x_c) on the others. One expand() per reduce().
  Eigen::VectorXd expand(const Eigen::VectorXd& x_c);

private:
  struct State;
  std::unique_ptr<State> state_;
  Eigen::MatrixXd S_;
};

} // namespace sig
