#pragma once
// Time marching without contact: the scheme applied step after step, the energy recorded at
// every step and the states kept at the output steps.
#include "integrator/energy.hpp"
#include "integrator/time_scheme.hpp"

#include <functional>
#include <vector>

namespace sig {

struct MarchHistory {
  std::vector<EnergyRecord> energy;  ///< steps 0 .. steps
  std::vector<DynamicState> outputs; ///< the initial state, then every output_every-th step
  DynamicState final_state;
};

/// Called after each step (progress lines, early inspection).
using StepObserver = std::function<void(const DynamicState&, const EnergyRecord&)>;

/// `steps` steps of `scheme` from `initial`; output_every = 0 keeps the initial and the final
/// states only. The work of the loads accumulates step_load(t_n) . (u_{n+1} - u_n).
MarchHistory march(const TimeScheme& scheme, const DynamicState& initial, int steps,
                   int output_every = 0, const StepObserver& observer = {});

} // namespace sig
