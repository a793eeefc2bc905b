#pragma once
// The convexification loop of FRICTION law=nonmonotone (solver/convexification.hpp) as the step
// solver of a march in velocity (integrator/linear_contact_march.hpp's StepSolver): every step
// freezes mu per node at the previous step's slip rate (CONVEXIFICATION start=previous, the
// march's default) and solves Coulomb problems on the step's condensed bulk until the slip rates
// settle. One code for both marches in velocity, the quasistatic one of ch. 5 and the backward
// Euler of ch. 6, and both dimensions: a node's slip rate has d - 1 components
// (solver/contact_bulk.hpp), its measure |w_t|.
#include "integrator/linear_contact_march.hpp"
#include "solver/solver_card.hpp"

#include <vector>

namespace sig {

struct HistoryInfo;

/// Per step 0 .. the last (step 0: none), the loop's counts: outer iterations, converged (1 or
/// 0) and the status cycle it broke (solver/convexification.hpp).
struct ConvexificationRecords {
  std::vector<double> outer{0}, outer_converged{1}, cycle{0};
  /// The total and the most outer iterations in one step.
  double total() const;
  double most() const;
};

/// The step solver of `contact`'s march on `scheme` with the SOLVER card's method and
/// CONVEXIFICATION options when a law of `contact` is nonmonotone, else empty (the march's own
/// Newton driver; `contact` null: no contact); each step appends its counts to `records`, which
/// must outlive the march, as `contact` and `scheme` must.
StepSolver convexification_step(const VelocityScheme& scheme, const VelocityContact* contact,
                                const SolverCard& solver, ConvexificationRecords& records);

/// case.hist's and steps.csv's columns of the loop (outer_iterations, outer_converged,
/// status_cycle) added to `info`, when the march ran it.
void add_convexification_columns(const ConvexificationRecords& records, HistoryInfo& info);

} // namespace sig
