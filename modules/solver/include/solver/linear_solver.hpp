#pragma once
// Sparse direct solvers behind one interface, MODULEF's habit of "same arguments, different
// module": a caller picks CHOLMOD, UMFPACK or MUMPS by name at run time and nothing else changes.
// The symbolic analysis (ordering, elimination tree) depends on the pattern only, so a Newton or
// active-set loop calls analyze() once and factorize() at every iteration.
#include "core/error.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <cstdint>
#include <memory>
#include <string>

namespace sig {

/// What the caller knows about the matrix; it selects the factorization (LL^T, LDL^T, LU).
enum class MatrixKind { spd, symmetric, general };

class LinearSolver {
public:
  virtual ~LinearSolver();

  /// Symbolic analysis (fill-reducing ordering). Valid while the sparsity pattern stays.
  virtual void analyze(const Eigen::SparseMatrix<double>& A) = 0;
  /// Numeric factorization. Analyzes first if nothing is analyzed or the pattern changed
  /// (pattern_fingerprint), so a new pattern costs an analysis, never a wrong factor.
  /// Throws FactorizationFailure with the backend's status if the matrix is singular or, for
  /// an spd factorization, not positive definite (sig::Error for the backend's other failures).
  virtual void factorize(const Eigen::SparseMatrix<double>& A) = 0;
  /// x = A^{-1} b with the last factorization.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  /// Several right sides at once (columns of B); the default solves them one by one.
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  /// Expressions (A * x, b - c) land here instead of being ambiguous between the two above.
  /// Backends that override solve() bring it back with `using LinearSolver::solve;`.
  template <class Derived> auto solve(const Eigen::MatrixBase<Derived>& B) const {
    if constexpr (Derived::ColsAtCompileTime == 1)
      return solve(Eigen::VectorXd(B));
    else
      return solve(Eigen::MatrixXd(B));
  }
  virtual std::string name() const = 0;
};

/// Identifies a sparsity pattern (dimensions, column starts, row indices; not the values).
std::uint64_t pattern_fingerprint(const Eigen::SparseMatrix<double>& A);

/// Backend names accepted by make_linear_solver.
inline constexpr const char* linear_solver_names = "cholmod|umfpack|mumps";

/// `name` is one of cholmod|umfpack|mumps; an unknown name, or a kind the backend cannot
/// factorize (CHOLMOD is spd only), is a sig::Error that lists the choices. `rank_rows`: the
/// solver of every rank of an mpirun job, each giving its rows (MumpsSolver's rank_rows): MUMPS
/// only, any other name a sig::Error.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, MatrixKind kind,
                                                 bool rank_rows = false);

/// What a backend offers beyond the LinearSolver interface, for the callers that choose how to
/// use it (the Schur complement's path, the kind of a symmetric matrix): they ask here, never
/// compare the backend's name.
struct BackendTraits {
  /// A Cholesky only (CHOLMOD): it factorizes spd matrices, so a symmetric matrix goes to it as
  /// spd (and fails if it is indefinite).
  bool cholesky = false;
  /// Factorizes a whole spd matrix with chosen unknowns ordered last and reads their Schur
  /// complement off the factor (CHOLMOD, solver/cholmod_split.hpp).
  bool split_schur = false;
  /// Forms a Schur complement by one partial factorization of the whole matrix (MUMPS,
  /// ICNTL(19), solver/mumps_solver.hpp).
  bool partial_schur = false;

  /// The kind a symmetric matrix is factorized as: spd on a Cholesky, symmetric (LDL^T) otherwise.
  MatrixKind symmetric_kind() const { return cholesky ? MatrixKind::spd : MatrixKind::symmetric; }
};

/// Rows of more than this many entries on average take nested dissection orders (and the
/// supernodal Schur split, solver/schur.hpp): a 2D P1 row has about 14 entries (7 nodes x 2), a
/// 3D P1 row about 45 (15 nodes x 3). On 2D meshes minimum degree orders are as good and
/// cheaper; on the 3D half ball of 158280 unknowns AMD's fill made MUMPS's analysis +
/// factorization 84 s against CHOLMOD-METIS's 23 s (drivers/bench-hertz3d.sh, issue 26).
constexpr double nested_dissection_entries_per_row = 30;

/// Whether A's rows are denser than nested_dissection_entries_per_row on average.
inline bool prefers_nested_dissection(const Eigen::SparseMatrix<double>& A) {
  return double(A.nonZeros()) > nested_dissection_entries_per_row * double(A.rows());
}

/// The traits of the backend `name` (as make_linear_solver); sig::Error listing the choices for
/// an unknown name.
BackendTraits backend_traits(const std::string& name);

std::string to_string(MatrixKind kind);

} // namespace sig
