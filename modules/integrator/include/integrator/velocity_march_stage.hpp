#pragma once
// What sig-march's two marches in velocity (integrator/quasistatic_stage.hpp, ch. 5, and
// integrator/dynamic_stage.hpp, ch. 6) share around their schemes: the march with its progress
// line, and the description of the run that case.hist records.
#include "integrator/linear_contact_march.hpp"
#include "integrator/time_card.hpp"
#include "integrator/velocity_history_io.hpp"

#include <functional>
#include <string>

namespace sig {

struct ContactElements;
struct SolverCard;

/// march_in_velocity over the TIME card's steps with a progress line "sig-march LABEL" whose
/// detail after each step is report(step) (which may record what it needs); a march that stops
/// ends its line with "STOPPED at step n" and warns with the failure.
VelocityHistory march_with_progress(LinearContactMarch& march, const VelocityScheme& scheme,
                                    const TimeParameters& time, const std::string& label,
                                    const std::function<std::string(const VelocityStep&)>& report);

/// The run as case.hist records it: the TIME card, the SOLVER card's backend and method ("linear"
/// without contact), the march's setup, and the contact elements' nodes and weights (null:
/// none).
VelocityHistoryInfo velocity_history_info(const TimeParameters& time, const SolverCard& solver,
                                          const LinearContactMarch& march,
                                          const ContactElements* elements);

/// Newton iterations of the steps done: the total and the most in one step.
std::pair<int, int> newton_iterations(const VelocityHistory& history);

} // namespace sig
