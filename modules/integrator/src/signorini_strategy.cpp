// Classical Signorini at the end of the step: u_n,i(t_{n+1}) <= bound_i, lambda_i >= 0,
// lambda_i (u_n,i - bound_i) = 0, solved by the static primal-dual active set method on the
// condensed step. Contact forces at t_{n+1} do work -lambda . (x_{n+1} - x_n) <= 0 on a node
// that arrives at the obstacle: the scheme loses the normal kinetic energy of the nodes that hit
// (the dissipation of Fig 8.3), and keeps the penetration at zero.
#include "integrator/dynamic_contact.hpp"
#include "integrator/strategies.hpp"

#include <numeric>

namespace sig {

ContactStepSolution SignoriniStrategy::solve(const NormalStep& step,
                                             const ContactBoundary& boundary) const {
  // Free flight: lambda = 0 satisfies every condition.
  if (!any_beyond(step.x_free, boundary.bound)) {
    ContactStepSolution s;
    s.lambda = Eigen::VectorXd::Zero(boundary.size());
    s.converged = true;
    return s;
  }
  std::vector<int> all(boundary.size());
  std::iota(all.begin(), all.end(), 0);
  return solve_with_static_method(step, boundary, all, boundary.bound, static_method("pdas", p_));
}

} // namespace sig
