// The Improved Penalized Method (IPM) of ch. 8.4, (8.30)-(8.32), frictionless: a Newton
// continuation in two phases over each step,
//   (a) the specific penalty (8.32) everywhere: -xi = r p(u_n), no bound;
//   (b) where (a)'s penetration stays below g, the same law; where it reaches g, the compliance
//       limited by the unilateral constraint, -xi in d phi_g(u_n) + L g: the penetration is held
//       at most g (the bound d + g: the CONT gap d plus the depth g) and the force is the specific
//       penalty at g plus a multiplier mu >= 0.
// Phase (b) is one bounded semi-smooth Newton (bounded_newton.hpp) started from (a)'s solution
// with (a)'s nodes beyond the bound active. The bound is checked at every node, so a node that
// (a) kept below g but that (b) pushes beyond it joins the active set (the continuation of the
// active-set iteration): the penetration is bounded by g at every node and step. The multiplier's
// work -mu (d + g - x_n) <= 0 is the only departure from the energy identity (3.53).
#include "integrator/dynamic_contact.hpp"
#include "integrator/strategies.hpp"

namespace sig {

ContactStepSolution ImprovedPenaltyStrategy::solve(const NormalStep& step,
                                                   const ContactBoundary& boundary) const {
  const NodalForceLaw law = specific_penalty_law(boundary, step.x_now, p_.r);
  // (a) specific penalty.
  const BoundedNewtonResult a = bounded_newton(step.A, step.x_free, law, {}, Eigen::VectorXd(),
                                               step.x_free, p_.max_iterations, p_.tolerance);
  if (!a.converged)
    return {a.lambda, false, "phase (a), specific penalty: " + a.failure, a.iterations};
  if (!any_beyond(a.x, boundary.bound)) return {a.lambda, true, "", a.iterations};

  // (b) bounded by the unilateral constraint x <= d + g.
  const std::vector<char> bounded(boundary.size(), 1);
  const BoundedNewtonResult b = bounded_newton(step.A, step.x_free, law, bounded, boundary.bound,
                                               a.x, p_.max_iterations, p_.tolerance);
  return {b.lambda, b.converged, b.converged ? "" : "phase (b), bounded: " + b.failure,
          a.iterations + b.iterations};
}

} // namespace sig
