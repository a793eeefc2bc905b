#pragma once
// A linear bulk condensed onto its contact dofs (DESIGN.md "Inside the modules"): S w = f, with
// S the Schur complement of the stiffness on the frame components of the contact nodes (normal
// only when frictionless, normal and tangential with friction) and f the condensed load. Every
// step of the contact driver is then a small dense problem, and this class makes each one cost
// O(n^2) instead of a dense factorization:
//
//  - the step matrix of a node the step leaves in its default state (no imposed component, the
//    method's default normal spring, no tangential force: a node off the obstacle) never
//    changes. B = S + eps I + D0 (D0 the default springs, eps the proximal term below) is
//    factorized by Cholesky, with the nodes ordered by decreasing initial gap, so the nodes
//    likely to touch come last;
//  - the trailing block L22 of the factor gives the Schur complement L22 L22^T of B onto any
//    tail of that order: a step solves the small dense problem of the tail that holds every
//    node with non-default conditions (the contact zone), the rest by triangular solves with
//    the leading block L11;
//  - when the tail is much longer than the zone (the zone away from the smallest gaps, or the
//    wide active set of an early iteration) and its dense problem would cost more than a new
//    factorization, the nodes are ordered again, the zone last, and B factorized again.
// This is the primal elimination (the contact rows are eliminated, never inverted), so a
// semi-coercive bulk (rigid modes held by contact alone) keeps its accuracy.
//
// Semi-coercive steps: every step carries a proximal term eps dw (eps = `regularization`). It
// makes a step with too few contact nodes to hold the rigid modes well posed (the Hertz
// problem's first iterate has one), and vanishes at convergence, where dw = 0.
#include "solver/contact_bulk.hpp"
#include "solver/dense_cholesky.hpp"

#include <Eigen/Dense>

#include <vector>

namespace sig {

struct CondensedProblem {
  Eigen::MatrixXd S;           ///< symmetric positive semi-definite, n x n
  Eigen::VectorXd f;           ///< condensed load, n
  std::vector<int> normal_dof; ///< per contact node: its w_n among the n unknowns
  /// per contact node: its w_t (2D) or w_t1, w_t2 (3D, node p's at 2 p and 2 p + 1), or empty
  /// without friction
  std::vector<int> tangential_dof;
  Eigen::VectorXd gap;       ///< d per contact node: q_n = w_n - d (the slip is w_t)
  double regularization = 0; ///< eps of the proximal term, >= 0
};

class CondensedBulk final : public ContactBulk {
public:
  /// `default_normal_stiffness` (one per contact node, may be empty: zeros) is the normal
  /// spring a node gets when nothing else is imposed on it (the projection method's Robin
  /// term); `start` the first iterate (empty: 0). sig::Error for inconsistent sizes or dofs.
  CondensedBulk(CondensedProblem problem, Eigen::VectorXd default_normal_stiffness = {},
                const Eigen::VectorXd& start = {});

  int contacts() const override { return static_cast<int>(p_.normal_dof.size()); }
  bool has_tangential() const override { return !p_.tangential_dof.empty(); }
  int tangents() const override { return tangents_; }
  Eigen::VectorXd penetration() const override;
  Eigen::VectorXd slip() const override;
  double equilibrium_residual(const Eigen::VectorXd& N, const Eigen::VectorXd& T) const override;
  double force_scale() const override;
  Eigen::VectorXd contact_stiffness() const override;
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd& normal_force) override;
  bool move(double alpha) override;
  void keep() override;
  void restore() override;
  void checkpoint() override;
  void rewind() override;
  double displacement_norm() const override { return w_.norm(); }
  double displacement_step() const override { return (w_ - base_).norm(); }
  bool nonlinear() const override { return false; }

  /// A new load f and new origins of the normal variables (gap: q_n = w_n - gap) on the same
  /// matrix, from the iterate `start` (empty: the present one): the next step of a march
  /// (integrator/linear_contact_march.hpp). The Cholesky factor and the tail's Schur complement
  /// are kept. sig::Error for inconsistent sizes.
  void restart(Eigen::VectorXd f, Eigen::VectorXd gap, const Eigen::VectorXd& start = {});

  /// The iterate w (all n unknowns).
  const Eigen::VectorXd& displacement() const { return w_; }
  /// Cholesky factorizations of the default step matrix so far (1 + reorders(), once factorized).
  int factorizations() const { return factorizations_; }
  /// Factorizations of a step's tail system: a step whose tail system repeats the last one (the
  /// same branches) reuses its factorization.
  int tail_factorizations() const { return tail_factorizations_; }
  /// Times the nodes were reordered (and B factorized again) to shorten the tail.
  int reorders() const { return reorders_; }

private:
  CondensedProblem p_;
  Eigen::VectorXd default_stiffness_; ///< per unknown: D0
  std::vector<int> order_;            ///< position -> unknown (far first)
  std::vector<int> position_;         ///< unknown -> position
  std::vector<int> node_start_;       ///< per contact node: the first position of its unknowns
  std::vector<int> node_of_;          ///< per unknown: its contact node, or -1
  std::vector<int> tangent_of_;       ///< per unknown: its tangent (0, 1), or -1
  int tangents_ = 1;                  ///< tangential unknowns per node, with friction
  Eigen::MatrixXd B_; ///< the permuted B, whole: its trailing blocks start every tail's H
  /// B_ factorized in place: the Cholesky factor L in the lower triangle (B's strict upper
  /// triangle is left above it, unread)
  Eigen::MatrixXd L_;
  bool factorized_ = false;
  int tail_start_ = -1; ///< position of the cached H
  Eigen::MatrixXd H_;   ///< L22 L22^T for tail_start_
  Eigen::VectorXd w_, base_, step_, kept_;
  Eigen::VectorXd Sw_, Sw_base_, S_step_, kept_Sw_; ///< S w_ and its pieces along the step
  Eigen::VectorXd checkpoint_w_, checkpoint_Sw_;    ///< the watchdog's iterate (checkpoint())
  Eigen::VectorXd last_normal_force_;               ///< N of the last solve, per contact node
  int reorders_ = 0;
  int factorizations_ = 0;
  /// The last tail system A of a step, kept with its factorization for the next step with the
  /// same A.
  RowMatrixXd tail_matrix_;
  bool tail_coupled_ = false;
  Eigen::LLT<Eigen::MatrixXd> tail_llt_;
  DenseLu tail_lu_;
  int tail_factorizations_ = 0;

  void order_nodes(const std::vector<int>& nodes);
  void reorder(const std::vector<char>& contact_zone);
  void factorize();
  void tail_schur(int start);
  bool is_default(int node, const NodeConditions& c) const;
};

} // namespace sig
