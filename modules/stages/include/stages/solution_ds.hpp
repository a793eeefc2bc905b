#pragma once
// DS "B", the solution of sig-solve (MODULEF's B: global vectors). Arrays: u (2 dofs per node,
// interleaved), method, linear (backend), converged, iterations, dofs, failure; for contact
// cases the contact state (put_contact_state) and history_active, history_entered,
// history_left, history_stick, history_slip,
// history_residual, history_increment, history_step_norm (E_k = ||x(k+1) - x(k)||),
// history_wall (the active set of each iteration); scalars
// time_<phase> in seconds. With a convexification loop (put_convexification): outer_* arrays.
// `iterations` counts every Newton iteration (of every convex solve).
#include "stages/static_solve.hpp"

#include <filesystem>

namespace sig {

class Ds;

/// The contact state per element: multiplier (normal nodal force), tangential_multiplier (m x 2
/// in 3D with friction: the force along the node's two tangents),
/// normal_status and friction_status (codes of contact/contact_status.hpp) and status (1 where
/// the normal status is not free, 0 elsewhere: the frictionless code, kept for old readers).
void put_contact_state(Ds& ds, const Eigen::VectorXd& normal, const Eigen::VectorXd& tangential,
                       const std::vector<NormalStatus>& normal_status,
                       const std::vector<FrictionStatus>& friction_status);

/// The iteration history: history_active (nodes on the wall), history_entered and history_left
/// (of them, nodes that came onto it since the previous iteration; nodes that came off it),
/// history_stick, history_slip, history_residual,
/// history_increment, history_step_norm (E_k = ||x(k+1) - x(k)||), history_kind (how the step
/// was taken: 0 relaxed, 1 an unheld step's cut, 2 monotone, 3 one branch change, 4 an escape
/// from a kink, as IterationRecord::kind), one entry per iteration;
/// history_wall [iterations x contact nodes], 1 where a node is on the wall in the iteration's
/// step.
void put_history(Ds& ds, const std::vector<IterationRecord>& history);

/// A solve that did not converge: failure_reason, the name of its NewtonFailure (summary.json's
/// failure), and drift, the length of the unbounded step, where the reason is drift.
void put_failure_reason(Ds& ds, bool converged, NewtonFailure reason, double drift);

/// The convexification loop: outer_converged, outer_iterations, outer_cycle (period of a status
/// cycle, 0 if none), outer_failure; per convex solve outer_inner_iterations,
/// outer_u_change, outer_xi_change, outer_mu_change, outer_status_changes,
/// outer_wall, outer_compliance, outer_stick, outer_slip; per contact element
/// friction_coefficient (the mu of the last convex solve).
void put_convexification(Ds& ds, const ConvexificationResult& loop);

void write_solution(const std::filesystem::path& path, const StaticSolution& solution,
                    const std::string& method, const std::string& backend,
                    const std::string& title);

} // namespace sig
