#pragma once
// The one march loop of every time march of the code: steps 1 .. N of a scheme hook
// (MarchScheme: linear elastodynamics with or without contact, integrator/elastodynamic_march.hpp;
// hyperelastic dynamics, stages/finite_strain_march.hpp; the marches in velocity,
// integrator/linear_contact_march.hpp). The loop owns what they share:
//  - the time stepping and the record of every step (StepRecord), row 0 the initial state;
//  - the energy bookkeeping: the work of the loads and of the contact forces summed over the
//    steps from each step's work (energy.hpp);
//  - the output selection: step 0, every output_every-th step and the last step done;
//  - an observer after each step (progress lines, early inspection);
//  - the stop at the first step that fails: the history ends with that step's record
//    (converged false), its failure names the step and why, and the last state done is kept.
// A hook takes one step and says what its steps record (MarchRecords): the optional parts of the
// history and of case.hist (stages/history_io.hpp).
#include "contact/contact_status.hpp"
#include "integrator/energy.hpp"
#include "integrator/time_scheme.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace sig {

/// Per contact node after a step (empty without contact).
struct ContactRecord {
  Eigen::VectorXd normal_force; ///< N (nodal force, pushing the body off)
  /// T (opposing the slip), d - 1 components per node with friction (3D: along the node's t1
  /// and t2, node i's at 2 i), one per node without
  Eigen::VectorXd tangential_force;
  std::vector<NormalStatus> normal_status;
  std::vector<FrictionStatus> friction_status;
  /// The marches in velocity: the normal velocity towards the obstacle and the tangential
  /// velocity (the slip rate; laid out as tangential_force: along t = (n2, -n1) in 2D, along t1
  /// and t2 in 3D with friction) (empty in the other marches).
  Eigen::VectorXd normal_velocity, tangential_velocity;
};

/// Wall seconds of a step: the whole (the loop's clock) and, in the marches in velocity, the
/// parts the hook times.
struct StepSeconds {
  double total = 0;
  double right_side = 0; ///< the scheme's right side b_n
  double contact = 0;    ///< the contact problem on the condensed bulk
};

/// One row of a march's history.
struct StepRecord {
  int step = 0;
  double time = 0;
  bool converged = true; ///< false: the step that stopped the march (its state not accepted)
  std::string failure;   ///< the hook's words for why, when not converged
  /// Newton iterations of the step (1 for a linear solve, 0 where the predictor was the step or
  /// at step 0).
  int iterations = 0;
  /// A linear contact march's step in free flight: the predictor (the step without contact
  /// force) was the step, no Newton iteration and no force (integrator/elastodynamic_march.hpp).
  bool free_flight = false;
  /// The energies after the step and the work done since step 0 (MarchRecords::energy,
  /// ::balance); a failed step repeats the last step done's.
  EnergyRecord energy;
  /// The work done over the step, from the hook; the loop sums it into `energy`.
  StepWork work;
  ContactRecord contact;
  StepSeconds seconds;
};

/// What a scheme's steps record beside their count, time and convergence: the optional parts of
/// the history (and of case.hist).
struct MarchRecords {
  bool energy = false;  ///< kinetic, elastic, total (and with contact the interface energy)
  bool balance = false; ///< the work of the loads and of the contact forces (the balance (8.34))
  /// Per step and contact node the velocities, forces and statuses, and the step's timed parts:
  /// the marches in velocity.
  bool contact_per_step = false;
};

/// The scheme hook: how one step is taken (the header).
class MarchScheme {
public:
  virtual ~MarchScheme() = default;
  virtual MarchRecords records() const = 0;
  /// The record of the state the march starts from (step 0).
  virtual StepRecord start() const = 0;
  /// Step n (1, 2, ...) from the last accepted state, which the hook then accepts. A step that
  /// fails returns converged = false and failure = why ("<what> did not converge after <k>
  /// iterations: <reason>"), leaving the state as it was; non-convergence is never thrown.
  virtual StepRecord step(int n) = 0;
  /// The state after the last accepted step (the marches in velocity: v is the velocity w).
  virtual DynamicState state() const = 0;
};

/// What a march leaves.
struct MarchHistory {
  MarchRecords records;
  /// Rows 0 (the initial state) .. the last step done, then the failed step if one stopped the
  /// march.
  std::vector<StepRecord> steps;
  std::vector<int> output_step;      ///< 0, every output_every-th step, the last step done
  std::vector<DynamicState> outputs; ///< the states at output_step
  bool converged = true;             ///< false if a step failed: the march stopped there
  std::string failure;               ///< names the step and why
  double seconds = 0;                ///< wall time of the steps

  /// The last state done (the last kept).
  const DynamicState& final_state() const { return outputs.back(); }
  /// The rows of the steps done (all but a failed last one).
  std::size_t steps_done() const { return steps.size() - (converged ? 0 : 1); }
};

/// Called after each step done, with its record and the state after it.
using StepObserver = std::function<void(const StepRecord&, const DynamicState&)>;

/// `steps` steps of `scheme`; output_every = 0 keeps the initial and the last states only.
MarchHistory march(MarchScheme& scheme, int steps, int output_every = 0,
                   const StepObserver& observer = {});

} // namespace sig
