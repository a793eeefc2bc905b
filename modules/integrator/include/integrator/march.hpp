#pragma once
// Time marching without contact: the scheme applied step after step, the energy recorded at
// every step and the states kept at the output steps.
#include "integrator/energy.hpp"
#include "integrator/time_scheme.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sig {

struct MarchHistory {
  std::vector<EnergyRecord> energy;  ///< steps 0 .. the last step done
  std::vector<DynamicState> outputs; ///< the initial state, then every output_every-th step
  DynamicState final_state;
  // With contact (integrator/contact_march.hpp, finite_strain_march.hpp):
  std::vector<Eigen::VectorXd> output_pressure; ///< N / weight at each kept state
  /// T / weight at each kept state, with friction (empty otherwise).
  std::vector<Eigen::VectorXd> output_tangential_pressure;
  bool converged = true; ///< false if a step's Newton failed: the march stopped before it
  std::string failure;   ///< names the step and why
};

/// Called after each step (progress lines, early inspection).
using StepObserver = std::function<void(const DynamicState&, const EnergyRecord&)>;

/// `steps` steps of `scheme` from `initial`; output_every = 0 keeps the initial and the final
/// states only. The work of the loads accumulates step_load(t_n) . (u_{n+1} - u_n).
MarchHistory march(const TimeScheme& scheme, const DynamicState& initial, int steps,
                   int output_every = 0, const StepObserver& observer = {});

} // namespace sig
