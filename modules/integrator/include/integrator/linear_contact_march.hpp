#pragma once
// The march in velocity on a linear bulk with node-to-rigid contact (ch. 5, and the base of the
// viscoelastodynamics of ch. 6). Each step n solves for the velocity w_n of the free dofs
//
//     S w_n + (contact forces of w_n) = b_n,
//
// with S a constant step matrix and b_n a right side built from the history, both given by a
// scheme (VelocityScheme below). The contact laws act on the frame components of w_n at each
// contact node: the laws in velocity of contact/contact_law.hpp (damped, damped-unilateral, with
// Coulomb or Tresca friction), q_n = v_n - origin the normal velocity towards the obstacle and
// q_t the tangential velocity (the slip rate).
//
// Cost. S is turned into nodal frames, factorized and condensed onto the contact components ONCE
// for the whole march (solver/contact_condensation.hpp); the small dense problem is factorized
// once more by the condensed bulk (solver/condensed_bulk.hpp), which every step restarts with its
// load. A step is then
//   1. b_n from the scheme and its condensation (with MUMPS the forward half of one solve);
//   2. the contact problem on the condensed bulk, warm-started from the previous step's velocity,
//      multipliers and branches, by the step solver (default: the one Newton driver,
//      solve_contact of solver/contact_newton.hpp);
//   3. the velocity of the whole bulk (the backward half of the solve), which the scheme accepts
//      and adds to its history.
// Without contact a step is one solve with S's factorization.
//
// Extension points: a new scheme or solve plugs in here, the march itself stays as it is.
//  - VelocityScheme (step_matrix, right_side, accept, normal_origin). The quasistatic Kelvin-Voigt
//    scheme with memory (integrator/kelvin_voigt_scheme.hpp) is one. The dynamic backward Euler in
//    velocity of ch. 6 is another: S = M / k + C + k K, b_n = f_n - K u_{n-1} + (M / k) w_{n-1},
//    accept: u_n = u_{n-1} + k w_n and keep w_n. A normal law in the displacement,
//    p(u_n - d) with u_n = u_{n-1} + k w_n, is a law in w_n with cn k in the ContactSetting and
//    the origin (d - u_{n-1,n}) / k per node, which normal_origin returns.
//  - StepSolver: how a step's contact problem is solved on the restarted condensed bulk. The
//    convexification loop of a nonmonotone friction law (solver/convexification.hpp: convexify on
//    the same bulk, setting and iterate) is a StepSolver, run inside every step.
#include "contact/contact_status.hpp"
#include "integrator/march.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sig {

class CondensedBulk;
class ContactCondensation;
class LinearSolver;

/// The contact nodes as the march sees them: their free dofs, normals and laws (no mesh), in the
/// body's dimension d = 2 or 3 (the normals' size).
struct VelocityContact {
  std::vector<int> first_dof;          ///< per node: the first of its d consecutive free dofs
  std::vector<Eigen::VectorXd> normal; ///< obstacle normal per node, d components
  ContactSetting setting;              ///< laws and nodal weights
  int size() const { return static_cast<int>(first_dof.size()); }
  int dim() const { return normal.empty() ? 2 : static_cast<int>(normal.front().size()); }
};

/// A one-step scheme in velocity on a linear bulk (header: the extension point).
class VelocityScheme {
public:
  virtual ~VelocityScheme() = default;
  virtual std::string name() const = 0;
  /// k, the uniform time step: t_n = n k.
  virtual double time_step() const = 0;
  /// S on the free dofs, symmetric positive definite (with the contact components held), the
  /// same at every step.
  virtual const Eigen::SparseMatrix<double>& step_matrix() const = 0;
  /// The step matrix holds only this rank's rows of an mpirun job (ViscoelasticProblem's
  /// rank_rows): the march factorizes it with MUMPS over the ranks; right sides are whole on
  /// every rank.
  virtual bool rank_rows() const { return false; }
  /// b_n of step n >= 1, from the steps accepted so far (1 .. n - 1).
  virtual Eigen::VectorXd right_side(int n) const = 0;
  /// Step n's velocity w_n (free dofs) is the solution: update the history.
  virtual void accept(int n, const Eigen::VectorXd& w) = 0;
  /// u after the last accepted step (free dofs).
  virtual const Eigen::VectorXd& displacement() const = 0;
  /// Per contact node, the origin of the normal variable at step n: q_n = (normal component of
  /// w_n) - origin. Default 0: the laws in velocity.
  virtual Eigen::VectorXd normal_origin(int n, const VelocityContact& contact) const;
  /// The scheme has an energy (the dynamic march; the quasistatic one has none).
  virtual bool has_energy() const { return false; }
  /// The energies after the last accepted step, where has_energy(): kinetic, elastic, total and,
  /// with contact (`contact` not null), the interface energy of the laws of the displacement.
  virtual EnergyRecord energy(const VelocityContact* contact) const;
};

/// How a step's contact problem is solved on the restarted bulk (header); the iterate holds the
/// previous step's multipliers and branches.
using StepSolver =
    std::function<ContactNewtonResult(ContactBulk&, const ContactSetting&, ContactIterate&)>;

/// The scheme hook of the march loop (integrator/march.hpp) for a VelocityScheme: its steps
/// record per contact node the velocities, forces and statuses, and the energies where the
/// scheme has them.
class LinearContactMarch final : public MarchScheme {
public:
  /// Factorizes and condenses the scheme's step matrix (once). `contact` null: a march without
  /// contact. parameters: the contact method and its Newton options (solver/contact_method.hpp);
  /// backend: cholmod | umfpack | mumps; `solver` empty: solve_contact. sig::Error if the step
  /// matrix cannot be factorized (a rigid motion held by nothing).
  LinearContactMarch(VelocityScheme& scheme, const VelocityContact* contact,
                     const ContactSolverParameters& parameters, const std::string& backend,
                     StepSolver solver = {});
  ~LinearContactMarch();
  LinearContactMarch(const LinearContactMarch&) = delete;
  LinearContactMarch& operator=(const LinearContactMarch&) = delete;

  MarchRecords records() const override;
  StepRecord start() const override;
  /// Step n = steps_done() + 1. A step whose contact solve does not converge is returned as it
  /// stands (converged false, the scheme's history unchanged), never thrown.
  StepRecord step(int n) override;
  /// u and w after the last accepted step, at t = steps_done() k.
  DynamicState state() const override;

  /// w of the last step (free dofs; 0 before the first).
  const Eigen::VectorXd& velocity() const { return w_; }
  int steps_done() const { return done_; }
  /// Sparse factorizations of the step matrix (1) and dense ones of its condensed problem (1,
  /// more if the condensed bulk reordered its nodes); seconds of the sparse one (frames and the
  /// Schur complement included).
  int sparse_factorizations() const { return 1; }
  int dense_factorizations() const;
  /// Factorizations of the condensed bulk's tail systems (one per set of branches met in a row;
  /// solver/condensed_bulk.hpp); 0 without contact.
  int tail_factorizations() const;
  double seconds_factorize() const { return seconds_factorize_; }
  /// MUMPS's ordering of the step matrix (empty with another backend).
  std::string ordering() const;
  /// The processes the step matrix is factorized over: the ranks of the mpirun job where the
  /// scheme's step matrix holds rank rows, else 1.
  int ranks() const;

private:
  VelocityScheme& scheme_;
  const VelocityContact* contact_;
  StepSolver solver_;
  std::unique_ptr<ContactMethod> method_;
  ContactNewtonOptions options_;
  std::unique_ptr<ContactCondensation> condensation_; ///< with contact
  std::unique_ptr<CondensedBulk> bulk_;               ///< with contact
  std::unique_ptr<LinearSolver> factor_;              ///< without contact
  ContactIterate iterate_;
  Eigen::VectorXd w_;
  int done_ = 0;
  double seconds_factorize_ = 0;
};

} // namespace sig
