// Alart-Curnier augmented Lagrangian, thesis section 3.1.1, (3.7)-(3.11), solved by a generalized
// Newton method on x = (u, lambda) with one Lagrange-multiplier unknown per contact element (the
// Lagrange node of the node-to-rigid element, Remark 3.1): the Newton vector is larger than the
// displacement vector by the number of Gamma3 nodes.
#include "contact/complementarity.hpp"
#include "solver/methods.hpp"

namespace sig {

namespace {

/// The augmented pressure lambda / w + r (u_n - g), whose positive part is the contact pressure.
Eigen::VectorXd augmented(const ContactProblem& problem, const Eigen::VectorXd& u,
                          const Eigen::VectorXd& lambda, double r) {
  return lambda.cwiseQuotient(problem.weight) + r * (problem.normal_part(u) - problem.gap);
}

/// ||R_L(x)|| = ||G(x) + F(x)|| of (3.10), the multiplier rows times r w so both read as forces.
double residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                const Eigen::VectorXd& lambda, double r) {
  const Eigen::VectorXd a = augmented(problem, u, lambda, r);
  const Eigen::VectorXd un = problem.normal_part(u);
  Eigen::VectorXd force(problem.contacts()), multiplier_rows(problem.contacts());
  for (int p = 0; p < problem.contacts(); ++p) {
    const double w = problem.weight[p];
    force[p] = w * positive_part(a[p]);
    multiplier_rows[p] = w * alart_curnier_normal(lambda[p] / w, un[p], problem.gap[p], r);
  }
  return std::hypot(equilibrium_residual(problem, u, force),
                    multiplier_rows.norm() / std::max(problem.f.norm(), 1e-300));
}

} // namespace

ContactSolution AugmentedLagrangian::solve(const ContactProblem& problem) const {
  const int m = problem.contacts();
  const double r = p_.r;
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(m);
  ContactSolution s;
  s.unknowns = problem.size() + m;

  // (i) x(0) = (0, 0).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.size());
  Eigen::VectorXd lambda = none;

  for (int k = 0; k < p_.max_iterations; ++k) {
    // (ii) x(k+1) = x(k) - (K_k + L_k)^{-1} (G + F)(x(k)), L_k in the generalized Jacobian of F:
    // per Lagrange node, the branch of [lambda + r (u_n - g)]_+ (derivative 1 on the closed
    // active side). On the active branch the multiplier row reads du_n = -(u_n - g), so
    // u_n(k+1) = g; on the other it reads dlambda = -lambda, so lambda(k+1) = 0. These rows are
    // eliminated and the displacement rows become one shared linear step; the multipliers of
    // active nodes are the reactions it returns.
    // The branch test [lambda + r (u_n - g)]_+ active is PDAS's test (3.20) with gamma = r.
    const std::vector<char> active =
        active_set(problem, u, lambda,
                   [r](double l, double un, double g) { return pdas_is_active(l, un, g, r); });

    LinearStep step;
    if (!solve_linear_step(problem, active, none, none, u, step)) {
      s.failure = "the generalized Jacobian is singular (active set of " +
                  std::to_string(count_active(active)) + " nodes)";
      break;
    }
    const Increment increment = increment_between(stack(step.u, step.reaction, problem.weight),
                                                  stack(u, lambda, problem.weight));
    u = step.u;
    lambda = step.reaction;
    const double res = residual(problem, u, lambda, r);
    s.history.push_back({count_active(active), res, increment.relative, increment.norm});
    s.active = active;

    // (iii) stop when ||x(k+1) - x(k)|| <= eps and ||R_L(x)|| <= eps.
    if (increment.relative <= p_.eps && res <= p_.eps) {
      s.converged = true;
      break;
    }
  }
  if (!s.converged && s.failure.empty()) s.failure = "no convergence within the iteration limit";
  s.u = u;
  s.multiplier = lambda;
  return s;
}

} // namespace sig
