#pragma once
// Time marching of a linear body with node-to-rigid contact: each step is the scheme's step plus
// the end-of-step contact forces of a strategy (integrator/contact_strategy.hpp), on the
// condensed problem of integrator/dynamic_contact.hpp:
//   1. the free step d_free = S^{-1} (2 f_bar - 2 K u_n + (4 / k) M v_n) (one sparse solve);
//   2. the strategy's forces N on the step condensed onto the normal displacements x = B u of the
//      p contact nodes (a CondensedBulk of the one contact driver, p unknowns), from x_n and
//      x_free = B (u_n + d_free);
//   3. d = d_free - 2 Z N, v_{n+1} = (2 / k) d - v_n (dense, Z kept from the start).
// Per step the record holds the energy (8.33), the work of the contact forces split as
// energy.hpp says, the maximal penetration [x_{n+1} - d]_+, the nodes with N > 0 and the
// strategy's iterations. A step whose Newton fails stops the march: the history holds the steps
// done, converged = false and the failure naming the step. Frictionless only: the condensation
// holds the normal displacements (a frictional linear body is refused).
#include "integrator/dynamic_contact.hpp"
#include "integrator/march.hpp"

namespace sig {

class ContactStrategy;

MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every = 0, const StepObserver& observer = {});

} // namespace sig
