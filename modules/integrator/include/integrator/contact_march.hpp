#pragma once
// Time marching with node-to-rigid contact: each step is the scheme's step plus the end-of-step
// contact forces of a strategy (integrator/contact_strategy.hpp), on the condensed problem of
// integrator/dynamic_contact.hpp:
//   1. the free step d_free = S^{-1} (2 f_bar - 2 K u_n + (4 / k) M v_n) (one sparse solve);
//   2. the strategy's forces lambda from x_n = B u_n and x_free = B (u_n + d_free) (p unknowns);
//   3. d = d_free - 2 Z lambda, v_{n+1} = (2 / k) d - v_n (dense, Z kept from the start).
// Per step the record holds the energy (8.33), the cumulated work of the contact forces
// -lambda . (x_{n+1} - x_n), the maximal penetration [x_{n+1} - d]_+, the nodes with lambda > 0
// and the strategy's iterations. A step whose Newton fails stops the march: the history holds
// the steps done, converged = false and the failure naming the step.
#include "integrator/dynamic_contact.hpp"
#include "integrator/march.hpp"

namespace sig {

class ContactStrategy;

MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every = 0, const StepObserver& observer = {});

} // namespace sig
