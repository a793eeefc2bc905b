#include "integrator/velocity_march_stage.hpp"

#include "contact/contact_elements.hpp"
#include "core/log.hpp"
#include "solver/solver_card.hpp"

#include <algorithm>

namespace sig {

VelocityHistory march_with_progress(LinearContactMarch& march, const VelocityScheme& scheme,
                                    const TimeParameters& time, const std::string& label,
                                    const std::function<std::string(const VelocityStep&)>& report) {
  Progress progress("sig-march " + label, time.steps, "time steps");
  std::string detail;
  const VelocityHistory history =
      march_in_velocity(march, scheme, time.steps, time.output_every, [&](const VelocityStep& s) {
        detail = report(s);
        progress.update(s.step, detail);
      });
  if (history.converged) {
    progress.finish(detail);
  } else {
    progress.finish(detail + "  STOPPED at step " + std::to_string(history.steps.back().step));
    log_warning("sig-march stopped: " + history.failure);
  }
  return history;
}

VelocityHistoryInfo velocity_history_info(const TimeParameters& time, const SolverCard& solver,
                                          const LinearContactMarch& march,
                                          const ContactElements* elements) {
  VelocityHistoryInfo info;
  info.scheme = time.scheme;
  info.backend = solver.backend;
  info.method = elements ? solver.parameters.method : "linear";
  info.k = time.k;
  info.T = time.final_time;
  info.steps = time.steps;
  info.output_every = time.output_every;
  info.seconds_factorize = march.seconds_factorize();
  info.dense_factorizations = march.dense_factorizations();
  if (elements) {
    info.contact_nodes = elements->node;
    info.weight = elements->weight;
  }
  return info;
}

std::pair<int, int> newton_iterations(const VelocityHistory& history) {
  int total = 0, most = 0;
  for (const VelocityStep& s : history.steps) {
    total += s.contact.iterations();
    most = std::max(most, s.contact.iterations());
  }
  return {total, most};
}

} // namespace sig
