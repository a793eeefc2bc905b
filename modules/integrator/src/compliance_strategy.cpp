// Normal compliance at the end of the step, -xi = r [u_n - d]_+ (1.24) with d the geometric gap:
// the foundation is a bed of springs of stiffness r per unit area, nodal force
// r w_i [x_i - d_i]_+. This is the static penalty method (Remark 3.2) on the condensed step.
// The force is evaluated at t_{n+1} only, so its work over a step is not the change of the spring
// energy: the scheme gains or loses energy at the impact depending on the step.
#include "integrator/dynamic_contact.hpp"
#include "integrator/strategies.hpp"

namespace sig {

ContactStepSolution ComplianceStrategy::solve(const NormalStep& step,
                                              const ContactBoundary& boundary) const {
  return solve_unilateral(step, boundary, boundary.geometric_gap, static_method("penalty", p_));
}

} // namespace sig
