#include "integrator/contact_march.hpp"

#include "core/error.hpp"
#include "integrator/contact_strategy.hpp"
#include "solver/condensed_bulk.hpp"

#include <numeric>
#include <sstream>

namespace sig {

MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every, const StepObserver& observer) {
  SIG_VERIFY(steps >= 0, "march: " << steps << " steps");
  SIG_VERIFY(output_every >= 0, "march: output_every = " << output_every << " must be >= 0");
  SIG_VERIFY(boundary.size() > 0, "march: a contact boundary without nodes");
  SIG_VERIFY(boundary.B.cols() == scheme.problem().num_dofs(),
             "march: the contact boundary has " << boundary.B.cols() << " dofs, the problem "
                                                << scheme.problem().num_dofs());
  SIG_VERIFY(!boundary.setting.has_friction(),
             "march: friction on a linear body is not implemented (the condensed step holds the "
             "normal displacements only)");
  const CondensedContact condensed = condense_contact(scheme, boundary);
  const double k = scheme.time_step();
  const int p = boundary.size();
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(p);
  std::vector<int> normal_dof(p);
  std::iota(normal_dof.begin(), normal_dof.end(), 0);

  MarchHistory history;
  history.energy.reserve(static_cast<std::size_t>(steps) + 1);
  history.energy.push_back(energy_record(scheme.problem(), initial, 0, 0.0));
  DynamicState state = initial;
  Eigen::VectorXd x_now = boundary.B * state.u;
  Eigen::VectorXd q_now = x_now - boundary.geometric_gap;
  {
    EnergyRecord& first = history.energy.back();
    first.interface = 0.0; // no secant law before the first step
    first.max_penetration = std::max(q_now.maxCoeff(), 0.0);
  }
  history.outputs.push_back(initial);
  history.output_pressure.push_back(no_force);
  bool last_kept = true;
  Eigen::VectorXd pressure = no_force;
  for (int n = 1; n <= steps; ++n) {
    // 1. The step without contact force.
    const Eigen::VectorXd f_bar = scheme.step_load(state.time);
    DynamicState next = scheme.advance(state, f_bar);
    const Eigen::VectorXd x_free = boundary.B * next.u;

    // 2. The strategy's forces at the end of the step, on the step condensed onto the normal
    //    displacements (dynamic_contact.hpp) written for the increment w = x - x_now:
    //    A w + N = A (x_free - x_now), q_n = w - (d - x_now), starting from the free step.
    CondensedProblem problem;
    problem.S = condensed.A;
    problem.f = condensed.A * (x_free - x_now);
    problem.normal_dof = normal_dof;
    problem.gap = boundary.geometric_gap - x_now;
    CondensedBulk bulk(std::move(problem), {}, x_free - x_now);
    const ContactStepStart start{q_now, boundary.B * state.v, k};
    const ContactStepSolution forces = strategy.solve(bulk, boundary.setting, start);
    if (!forces.converged) {
      std::ostringstream why;
      why << "step " << n << " (t = " << state.time + k << "): " << strategy.name()
          << " did not converge after " << forces.iterations << " iterations: " << forces.failure;
      history.converged = false;
      history.failure = why.str();
      break;
    }

    // 3. Their response: d = d_free - 2 Z N. In free flight N = 0 and the free step is the step.
    if ((forces.normal_force.array() != 0.0).any()) {
      const Eigen::VectorXd correction = condensed.Z * forces.normal_force;
      next.u -= 2.0 * correction;
      next.v -= (4.0 / k) * correction;
    }
    const Eigen::VectorXd x_next = boundary.B * next.u;
    const Eigen::VectorXd q_next = x_next - boundary.geometric_gap;
    EnergyRecord record =
        energy_record(scheme.problem(), next, n,
                      history.energy.back().external_work + f_bar.dot(next.u - state.u));
    add_contact_step(record, history.energy.back(), forces.normal_force, no_force, q_now, q_next,
                     no_force, interface_energy(forces.law, boundary.setting.weight, q_next));
    record.newton_iterations = forces.iterations;
    state = std::move(next);
    x_now = x_next;
    q_now = q_next;
    pressure = forces.normal_force.cwiseQuotient(boundary.setting.weight);
    history.energy.push_back(record);
    last_kept = output_every > 0 ? n % output_every == 0 : n == steps;
    if (last_kept) {
      history.outputs.push_back(state);
      history.output_pressure.push_back(pressure);
    }
    if (observer) observer(state, history.energy.back());
  }
  // A march stopped early keeps its last good state.
  if (!last_kept) {
    history.outputs.push_back(state);
    history.output_pressure.push_back(pressure);
  }
  history.final_state = state;
  return history;
}

} // namespace sig
