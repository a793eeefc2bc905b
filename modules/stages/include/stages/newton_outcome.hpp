#pragma once
// How a contact Newton ended, as the stages' results record it (StaticSolution, LoadStepResult):
// one copy for the fields every result carries alike.
#include "solver/contact_newton.hpp"

namespace sig {

/// Converged or not, why not (the reason, its details, the drift's length) and every iteration.
template <class Result>
void record_newton_outcome(Result& result, const ContactNewtonResult& newton) {
  result.converged = newton.converged;
  result.reason = newton.reason;
  result.failure = newton.failure;
  result.drift = newton.drift;
  result.history = newton.history;
}

} // namespace sig
