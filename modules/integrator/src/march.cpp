#include "integrator/march.hpp"

#include "core/error.hpp"
#include "core/log.hpp"

#include <sstream>

namespace sig {

namespace {

void keep(MarchHistory& history, int step, DynamicState state) {
  history.output_step.push_back(step);
  history.outputs.push_back(std::move(state));
}

} // namespace

MarchHistory march(MarchScheme& scheme, int steps, int output_every, const StepObserver& observer) {
  SIG_VERIFY(steps >= 0, "march: " << steps << " steps");
  SIG_VERIFY(output_every >= 0, "march: output_every = " << output_every << " must be >= 0");
  MarchHistory history;
  history.records = scheme.records();
  history.steps.reserve(static_cast<std::size_t>(steps) + 1);
  history.steps.push_back(scheme.start());
  keep(history, 0, scheme.state());
  const Stopwatch clock;
  for (int n = 1; n <= steps; ++n) {
    const Stopwatch step_clock;
    StepRecord record = scheme.step(n);
    record.step = n;
    record.seconds.total = step_clock.seconds();
    const StepRecord& before = history.steps.back();
    if (!record.converged) {
      std::ostringstream why;
      why << "step " << n << " (t = " << record.time << "): " << record.failure;
      history.converged = false;
      history.failure = why.str();
      record.energy = before.energy; // no state was accepted
      history.steps.push_back(std::move(record));
      break;
    }
    add_step_work(record.energy, before.energy, record.work);
    history.steps.push_back(std::move(record));
    const bool output = (output_every > 0 && n % output_every == 0) || n == steps;
    if (output || observer) {
      DynamicState state = scheme.state();
      if (observer) observer(history.steps.back(), state);
      if (output) keep(history, n, std::move(state));
    }
  }
  // A march stopped early keeps its last good state.
  const int last_done = static_cast<int>(history.steps_done()) - 1;
  if (history.output_step.back() != last_done) keep(history, last_done, scheme.state());
  history.seconds = clock.seconds();
  return history;
}

} // namespace sig
