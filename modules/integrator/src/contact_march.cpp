#include "integrator/contact_march.hpp"

#include "core/error.hpp"
#include "integrator/contact_strategy.hpp"

#include <sstream>

namespace sig {

namespace {

int count_positive(const Eigen::VectorXd& lambda) {
  return static_cast<int>((lambda.array() > 0).count());
}

} // namespace

MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every, const StepObserver& observer) {
  SIG_VERIFY(steps >= 0, "march: " << steps << " steps");
  SIG_VERIFY(output_every >= 0, "march: output_every = " << output_every << " must be >= 0");
  SIG_VERIFY(boundary.size() > 0, "march: a contact boundary without nodes");
  SIG_VERIFY(boundary.B.cols() == scheme.problem().num_dofs(),
             "march: the contact boundary has " << boundary.B.cols() << " dofs, the problem "
                                                << scheme.problem().num_dofs());
  const CondensedContact condensed = condense_contact(scheme, boundary);
  const double k = scheme.time_step();
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(boundary.size());

  MarchHistory history;
  history.energy.reserve(static_cast<std::size_t>(steps) + 1);
  history.energy.push_back(energy_record(scheme.problem(), initial, 0, 0.0));
  history.energy.back().max_penetration = boundary.penetration(boundary.B * initial.u).maxCoeff();
  history.outputs.push_back(initial);
  history.output_pressure.push_back(no_force);
  DynamicState state = initial;
  Eigen::VectorXd x_now = boundary.B * state.u;
  double external_work = 0.0, contact_work = 0.0;
  bool last_kept = true;
  Eigen::VectorXd pressure = no_force;
  for (int n = 1; n <= steps; ++n) {
    // 1. The step without contact force.
    const Eigen::VectorXd f_bar = scheme.step_load(state.time);
    DynamicState next = scheme.advance(state, f_bar);
    const Eigen::VectorXd x_free = boundary.B * next.u;

    // 2. The strategy's end-of-step forces.
    const ContactStepSolution forces =
        strategy.solve(NormalStep{condensed.A, x_now, x_free}, boundary);
    if (!forces.converged || !forces.lambda.allFinite()) {
      std::ostringstream why;
      why << "step " << n << " (t = " << state.time + k << "): " << strategy.name()
          << " did not converge after " << forces.iterations << " iterations: "
          << (forces.failure.empty() ? "non-finite contact forces" : forces.failure);
      history.converged = false;
      history.failure = why.str();
      break;
    }

    // 3. Their response: d = d_free - 2 Z lambda.
    //    In free flight lambda = 0 and the free step is the step.
    if ((forces.lambda.array() != 0.0).any()) {
      const Eigen::VectorXd correction = condensed.Z * forces.lambda;
      next.u -= 2.0 * correction;
      next.v -= (4.0 / k) * correction;
    }
    const Eigen::VectorXd x_next = boundary.B * next.u;
    external_work += f_bar.dot(next.u - state.u);
    contact_work -= forces.lambda.dot(x_next - x_now);
    state = std::move(next);
    x_now = x_next;

    EnergyRecord record = energy_record(scheme.problem(), state, n, external_work);
    record.contact_work = contact_work;
    record.max_penetration = boundary.penetration(x_now).maxCoeff();
    record.active_nodes = count_positive(forces.lambda);
    record.newton_iterations = forces.iterations;
    pressure = forces.lambda.cwiseQuotient(boundary.weight);
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
