// Classical Signorini at the end of the step: u_n,i(t_{n+1}) <= bound_i, lambda_i >= 0,
// lambda_i (u_n,i - bound_i) = 0, solved by the static primal-dual active set method on the
// condensed step. Contact forces at t_{n+1} do work -lambda . (x_{n+1} - x_n) <= 0 on a node
// that arrives at the obstacle: the scheme loses the normal kinetic energy of the nodes that hit
// (the dissipation of Fig 8.3), and keeps the penetration at zero.
#include "integrator/dynamic_contact.hpp"
#include "integrator/strategies.hpp"

namespace sig {

ContactStepSolution SignoriniStrategy::solve(const NormalStep& step,
                                             const ContactBoundary& boundary) const {
  return solve_unilateral(step, boundary, boundary.bound, static_method("pdas", p_));
}

} // namespace sig
