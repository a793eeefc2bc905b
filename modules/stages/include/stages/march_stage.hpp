#pragma once
// What sig-march's marches share around their scheme hooks (integrator/march.hpp): the march
// with its progress line, the Newton iterations counted, and the description of a march in
// velocity (stages/quasistatic_stage.hpp, ch. 5, and stages/dynamic_stage.hpp, ch. 6) that
// case.hist records.
#include "integrator/linear_contact_march.hpp"
#include "stages/history_io.hpp"
#include "stages/time_card.hpp"

#include <functional>
#include <string>
#include <utility>

namespace sig {

struct ContactElements;
struct SolverCard;

/// The march loop over the TIME card's steps with a progress line "sig-march LABEL" whose
/// detail after each step is report(record, state) (which may record what it needs); a march
/// that stops ends its line with "STOPPED at step n" and warns with the failure.
MarchHistory march_with_progress(
    MarchScheme& scheme, const TimeParameters& time, const std::string& label,
    const std::function<std::string(const StepRecord&, const DynamicState&)>& report);

/// The run as case.hist records it: the TIME card, the linear solver's backend and the contact
/// elements' nodes, weights and friction (null: none).
HistoryInfo history_info(const TimeParameters& time, const std::string& linear,
                         const ContactElements* elements);

/// The run of a march in velocity as case.hist records it: the TIME card, the SOLVER card's
/// backend and method ("linear" without contact), the march's setup, and the contact elements'
/// nodes, weights and friction (null: none).
HistoryInfo velocity_history_info(const TimeParameters& time, const SolverCard& solver,
                                  const LinearContactMarch& march, const ContactElements* elements);

/// Newton iterations of the steps done: the total and the most in one step.
std::pair<int, int> newton_iterations(const MarchHistory& history);

} // namespace sig
