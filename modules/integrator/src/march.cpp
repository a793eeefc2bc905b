#include "integrator/march.hpp"

#include "core/error.hpp"

namespace sig {

MarchHistory march(const TimeScheme& scheme, const DynamicState& initial, int steps,
                   int output_every, const StepObserver& observer) {
  SIG_VERIFY(steps >= 0, "march: " << steps << " steps");
  SIG_VERIFY(output_every >= 0, "march: output_every = " << output_every << " must be >= 0");
  MarchHistory history;
  history.energy.reserve(static_cast<std::size_t>(steps) + 1);
  history.energy.push_back(energy_record(scheme.problem(), initial, 0, 0.0));
  history.outputs.push_back(initial);
  DynamicState state = initial;
  double work = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const Eigen::VectorXd f_bar = scheme.step_load(state.time);
    DynamicState next = scheme.advance(state, f_bar);
    work += f_bar.dot(next.u - state.u);
    state = std::move(next);
    history.energy.push_back(energy_record(scheme.problem(), state, n, work));
    history.energy.back().newton_iterations = 1;
    const bool output = output_every > 0 ? n % output_every == 0 : n == steps;
    if (output) history.outputs.push_back(state);
    if (observer) observer(state, history.energy.back());
  }
  history.final_state = state;
  return history;
}

} // namespace sig
