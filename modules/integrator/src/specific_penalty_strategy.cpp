// The specific penalty of [62], thesis (3.51) and (8.32): nodal force r w_i p(a_i, b_i) with
// a_i, b_i the penetrations x_i - d_i at t_n and t_{n+1} (integrator/specific_penalty.hpp).
// Its work over the step is -(r / 2) w_i ([b_i]_+^2 - [a_i]_+^2), so the midpoint rule conserves
// E + (r / 2) sum_i w_i [x_i - d_i]_+^2 exactly (3.53); the penetration is not zero (0.0034 m in
// scene 8a). p is non-decreasing in b: the step is a strictly convex problem, solved by the
// semi-smooth Newton method of bounded_newton.hpp without bounds.
#include "integrator/bounded_newton.hpp"
#include "integrator/dynamic_contact.hpp"
#include "integrator/specific_penalty.hpp"
#include "integrator/strategies.hpp"

namespace sig {

/// phi_i(x) = r w_i p(a_i, x_i - d_i), shared with ipm.cpp.
NodalForceLaw specific_penalty_law(const ContactBoundary& boundary, const Eigen::VectorXd& x_now,
                                   double r) {
  const Eigen::VectorXd a = x_now - boundary.geometric_gap;
  return
      [&boundary, a, r](const Eigen::VectorXd& x, Eigen::VectorXd& force, Eigen::VectorXd& slope) {
        for (Eigen::Index i = 0; i < x.size(); ++i) {
          const double b = x[i] - boundary.geometric_gap[i];
          force[i] = r * boundary.weight[i] * specific_penalty(a[i], b);
          slope[i] = r * boundary.weight[i] * d_specific_penalty(a[i], b);
        }
      };
}

ContactStepSolution SpecificPenaltyStrategy::solve(const NormalStep& step,
                                                   const ContactBoundary& boundary) const {
  const BoundedNewtonResult n =
      bounded_newton(step.A, step.x_free, specific_penalty_law(boundary, step.x_now, p_.r), {},
                     Eigen::VectorXd(), step.x_free, p_.max_iterations, p_.tolerance);
  return {n.lambda, n.converged, n.failure, n.iterations};
}

} // namespace sig
