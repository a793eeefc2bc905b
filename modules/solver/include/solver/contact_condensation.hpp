#pragma once
// A linear bulk K u = f (on its free dofs) turned into the nodal frames of its contact nodes and
// condensed once onto their frame components (solver/nodal_frames.hpp, solver/schur.hpp): the
// normal displacement of each node towards the obstacle, and its slip when the contact has
// friction. One sparse factorization, at construction; then any number of loads, each condensed
// onto the contact components (condense) and its solution expanded back to the whole bulk
// (expand): with MUMPS the pair is one solve split around the Schur problem, so a load costs one
// forward-backward substitution whatever the contact problem in between.
//
// The static solve (one load) and the linear-bulk march (integrator/linear_contact_march.hpp: a
// load per time step with the step matrix in place of K) share it: the contact methods iterate on
// problem()'s small dense matrix, which the condensed bulk (solver/condensed_bulk.hpp) factorizes
// once more, densely.
#include "contact/contact_law.hpp"
#include "solver/condensed_bulk.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sig {

class FrameRotation;
class SchurComplement;
struct MumpsStatistics;

class ContactCondensation {
public:
  /// K: symmetric, on the free dofs; first_dofs[p]: the first of the d consecutive free dofs of
  /// contact node p, frames[p] its d x d contact frame (contact_frame: tangents, then -n);
  /// `tangential`: the slips are unknowns too (friction). backend: cholmod | umfpack | mumps.
  /// sig::Error when the frames differ in size, a node appears twice, or the bulk with the
  /// contact components held cannot be
  /// factorized: then a rigid motion of the body is held by nothing (the message says so).
  /// `positive_definite`: K itself is (a body held by Dirichlet conditions, the step matrix of a
  /// march), which lets CHOLMOD factorize it whole and split its solves (solver/schur.hpp).
  /// `rank_rows`: K holds only this rank's rows of an mpirun job (SchurComplement's rank_rows);
  /// loads are the whole ones, on every rank.
  ContactCondensation(Eigen::SparseMatrix<double> K, std::vector<int> first_dofs,
                      std::vector<ContactFrame> frames, bool tangential, const std::string& backend,
                      bool positive_definite = false, bool rank_rows = false);
  ~ContactCondensation();
  ContactCondensation(const ContactCondensation&) = delete;
  ContactCondensation& operator=(const ContactCondensation&) = delete;

  int contacts() const { return static_cast<int>(frames_of_nodes_.size()); }
  bool tangential() const { return !tangential_dof_.empty(); }
  /// Per contact node, the place of its normal unknown among the condensed unknowns; of its
  /// slips (d - 1 a node, node p's at (d - 1) p + k), empty without friction.
  const std::vector<int>& normal_unknowns() const { return normal_dof_; }
  const std::vector<int>& tangential_unknowns() const { return tangential_dof_; }
  /// The Schur complement onto the condensed unknowns (problem()'s S, without a load).
  const Eigen::MatrixXd& schur() const;

  /// The small problem of the load f (free dofs): the Schur complement, condense(f), the
  /// unknowns of each node, origins (gap) 0 and the proximal weight of the static solve
  /// (kRelativeRegularization times S's largest diagonal entry).
  CondensedProblem problem(const Eigen::VectorXd& f);
  /// The condensed load of f (free dofs, original frame); remembered for expand().
  Eigen::VectorXd condense(const Eigen::VectorXd& f);
  /// The free dofs (original frame) of condensed unknowns w under the load of the last condense().
  Eigen::VectorXd expand(const Eigen::VectorXd& w);
  /// The condensed unknowns (frame components) of a free-dof vector u: a warm start.
  Eigen::VectorXd restrict(const Eigen::VectorXd& u) const;
  /// ||K u - f + contact forces|| / ||f|| for free dofs u (original frame), the load of the last
  /// condense() and nodal contact forces N (normal) and T (tangential, d - 1 per node along the
  /// node's tangents, ignored without friction).
  double relative_residual(const Eigen::VectorXd& u, const Eigen::VectorXd& N,
                           const Eigen::VectorXd& T) const;

  /// Wall-clock seconds of the frames, the sparse factorization and the forming of S.
  double seconds_frames() const { return seconds_frames_; }
  double seconds_factorize() const;
  double seconds_schur() const;
  /// The ordering of the sparse factorization (SchurComplement::ordering).
  std::string ordering() const;
  /// MUMPS's statistics of that factorization (SchurComplement::mumps_statistics).
  const MumpsStatistics* mumps_statistics() const;

private:
  Eigen::SparseMatrix<double> K_; ///< in frames
  std::vector<ContactFrame> frames_of_nodes_;
  std::vector<int> first_;     ///< per contact node: its first dof, the others following
  int d_ = 2;                  ///< dofs per node
  std::vector<int> interface_; ///< sorted free dofs of the condensed unknowns
  std::vector<int> normal_dof_, tangential_dof_;
  std::unique_ptr<FrameRotation> frames_;
  std::unique_ptr<SchurComplement> schur_;
  Eigen::VectorXd load_; ///< the last condensed load, in frames
  bool rank_rows_ = false;
  double seconds_frames_ = 0;
};

/// Why a body whose contact components are held cannot be factorized, or whose converged contact
/// solve is out of equilibrium.
inline constexpr const char* kUnheldRigidMotion =
    "a rigid motion of the body is held neither by its Dirichlet conditions nor by the "
    "directions of its contact laws (a tangential load on a frictionless body without Dirichlet "
    "condition?): there is no equilibrium to find";

/// The weight of the vanishing proximal term of a condensed problem, relative to the largest
/// entry of its matrix (condensed_bulk.hpp): enough to pin the rigid modes a single contact node
/// leaves free (Hertz's first iterate, thesis Fig 7.8), far below round-off at convergence.
inline constexpr double kRelativeRegularization = 1e-10;

} // namespace sig
