#pragma once
// Static condensation of a linear bulk onto its contact dofs. Where the bulk is linear, contact
// lives on Gamma3 only: with c the interface dofs (the 2 dofs of every Gamma3 node) and i the
// others,
//   [K_ii K_ic] [u_i]   [f_i]          S u_c = f_c - K_ci K_ii^{-1} f_i,
//   [K_ci K_cc] [u_c] = [f_c]   <=>    u_i   = K_ii^{-1} (f_i - K_ic u_c),
// with S = K_cc - K_ci K_ii^{-1} K_ic. One sparse factorization of K_ii then serves every
// iteration of a contact solver, which works on the small dense S.
//
// K may be singular (a semi-coercive problem such as Hertz keeps rigid modes) as long as K_ii,
// the bulk with the interface clamped, is positive definite: S is then positive semi-definite
// with the rigid modes restricted to c as its kernel. K itself is factorized only by the CHOLMOD
// split below, whose supernodal layout shifts K_cc so that K_ii alone need be positive definite.
#include "solver/linear_solver.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sig {

class CholmodSplitSolver;
class MumpsSolver;
struct MumpsStatistics;

namespace detail {
/// Solves K_ii y = r (columns of r in interior order); one kind per backend path (schur.cpp).
class InteriorSolver;
} // namespace detail

class SchurComplement {
public:
  /// K: n x n symmetric, stored full, reduced to free dofs. interface_dofs: sorted, distinct,
  /// 0-based, at least one and fewer than n. backend: cholmod|umfpack|mumps; "mumps" takes
  /// K_ii's factor and S from one partial factorization (ICNTL(19)), the others factorize K_ii
  /// and solve for the columns of K_ic in blocks. kind describes K_ii (spd for a clamped bulk).
  /// `whole_positive_definite`: the caller knows K itself positive definite (the whole body
  /// held by Dirichlet conditions); with "cholmod" K is then factorized whole, the interface
  /// ordered last (solver/cholmod_split.hpp, simplicial), S read off the factor and a
  /// condense/expand pair costs one forward-backward substitution instead of two interior
  /// solves. With "cholmod" on rows of 3D fill (prefers_nested_dissection, solver/
  /// linear_solver.hpp) K is factorized so whatever this flag (supernodal, K_cc shifted): the
  /// block solves cost several factorizations there. If that factorization fails the interior
  /// path above is taken. `rank_rows`: K holds only this
  /// rank's rows of an mpirun job (solver/mpi_session.hpp), which "mumps" factorizes with the
  /// other ranks' (MumpsSolver's rank_rows); loads are then the whole ones, on every rank.
  SchurComplement(const Eigen::SparseMatrix<double>& K, std::vector<int> interface_dofs,
                  const std::string& backend, MatrixKind kind = MatrixKind::spd,
                  bool whole_positive_definite = false, bool rank_rows = false);
  ~SchurComplement();
  SchurComplement(const SchurComplement&) = delete;
  SchurComplement& operator=(const SchurComplement&) = delete;

  /// S (m x m, symmetric), rows and columns in the order of interface_dofs().
  const Eigen::MatrixXd& matrix() const { return S_; }
  /// The condensed load f_c - K_ci K_ii^{-1} f_i of a full load f (size n).
  Eigen::VectorXd condense(const Eigen::VectorXd& f);
  /// The full displacement: u_c on the interface, u_i = K_ii^{-1} (f_i - K_ic u_c) inside.
  /// With MUMPS, expanding the load of the last condense() continues its solve (the backward
  /// substitution after condense()'s forward elimination, ICNTL(26)): the pair costs one solve;
  /// so does the CHOLMOD split (constructor).
  Eigen::VectorXd expand(const Eigen::VectorXd& f, const Eigen::VectorXd& u_c);

  const std::vector<int>& interface_dofs() const { return interface_; }
  const std::vector<int>& interior_dofs() const { return interior_; }
  int size() const { return static_cast<int>(interface_.size() + interior_.size()); }
  const std::string& backend() const { return backend_; }
  /// The fill-reducing ordering of MUMPS's analysis ("amd", "scotch", ...); empty for the others.
  std::string ordering() const;
  /// MUMPS's statistics of its partial factorization; null for the other backends.
  const MumpsStatistics* mumps_statistics() const;
  /// Wall-clock seconds of the analysis and factorization (for MUMPS: including S).
  double seconds_factorize() const { return seconds_factorize_; }
  /// Wall-clock seconds spent forming S after the factorization (block solves, symmetrization).
  double seconds_schur() const { return seconds_schur_; }

private:
  std::string backend_;
  std::vector<int> interface_;
  std::vector<int> interior_;
  Eigen::SparseMatrix<double> K_ic_;
  Eigen::MatrixXd S_;
  std::unique_ptr<detail::InteriorSolver> interior_solver_;
  MumpsSolver* mumps_ = nullptr; ///< the partial factorization, when the backend is MUMPS
  bool rank_rows_ = false;       ///< K_ic_ holds this rank's rows only: its products are summed
  std::unique_ptr<CholmodSplitSolver> split_; ///< K factorized whole (CHOLMOD, constructor)
  bool split_reduced_ = false;                ///< split_ holds condense()'s forward substitution
  Eigen::VectorXd condensed_load_; ///< f of the last condense() that expand() can continue
  double seconds_factorize_ = 0;
  double seconds_schur_ = 0;

  Eigen::VectorXd interior_part(const Eigen::VectorXd& v) const;
  Eigen::VectorXd interface_part(const Eigen::VectorXd& v) const;
};

} // namespace sig
