#include "stages/march_stage.hpp"

#include "contact/contact_elements.hpp"
#include "core/log.hpp"
#include "solver/mpi_session.hpp"
#include "solver/solver_card.hpp"

#include <algorithm>

namespace sig {

MarchHistory march_with_progress(
    MarchScheme& scheme, const TimeParameters& time, const std::string& label,
    const std::function<std::string(const StepRecord&, const DynamicState&)>& report) {
  Progress progress("sig-march " + label, time.steps, "time steps");
  std::string detail;
  // The ranks of an mpirun job march together: the host alone shows it.
  const bool host = mpi::rank() == 0;
  const MarchHistory history = march(scheme, time.steps, time.output_every,
                                     [&](const StepRecord& record, const DynamicState& state) {
                                       detail = report(record, state);
                                       if (host) progress.update(record.step, detail);
                                     });
  if (!host) return history;
  if (history.converged) {
    progress.finish(detail);
  } else {
    progress.finish(detail + "  STOPPED at step " + std::to_string(history.steps.back().step));
    log_warning("sig-march stopped: " + history.failure);
  }
  return history;
}

HistoryInfo history_info(const TimeParameters& time, const std::string& linear,
                         const ContactElements* elements) {
  HistoryInfo info;
  info.scheme = time.scheme;
  info.linear = linear;
  info.k = time.k;
  info.T = time.final_time;
  info.steps = time.steps;
  info.output_every = time.output_every;
  if (elements) {
    info.contact_nodes = elements->node;
    info.weight = elements->weight;
    info.friction = any_friction(elements->law);
  }
  return info;
}

HistoryInfo velocity_history_info(const TimeParameters& time, const SolverCard& solver,
                                  const LinearContactMarch& march,
                                  const ContactElements* elements) {
  HistoryInfo info = history_info(time, solver.backend, elements);
  info.setup = HistoryInfo::Setup{march.seconds_factorize(), march.dense_factorizations(),
                                  elements ? solver.parameters.method : "linear"};
  info.ordering = march.ordering();
  info.ranks = march.ranks();
  return info;
}

std::pair<int, int> newton_iterations(const MarchHistory& history) {
  int total = 0, most = 0;
  for (std::size_t s = 1; s < history.steps.size(); ++s) {
    total += history.steps[s].iterations;
    most = std::max(most, history.steps[s].iterations);
  }
  return {total, most};
}

} // namespace sig
