// Primal-dual active set, thesis section 3.2, (3.20)-(3.32): a semi-smooth Newton method on the
// complementarity function lambda - [lambda + gamma (u_n - g)]_+. Active nodes get the Dirichlet
// condition u_n = g (3.31), inactive ones the Neumann condition lambda = 0 (3.32); no multiplier
// unknowns are added to the system.
#include "contact/complementarity.hpp"
#include "solver/methods.hpp"

namespace sig {

namespace {

/// Step (ii): A(k+1) = { p : lambda_p + gamma (u_n,p - g_p) >= 0 }.
std::vector<char> pdas_active_set(const ContactProblem& problem, const Eigen::VectorXd& u,
                                  const Eigen::VectorXd& lambda, double gamma) {
  return active_set(problem, u, lambda, [gamma](double l, double un, double g) {
    return pdas_is_active(l, un, g, gamma);
  });
}

/// ||R(u, lambda)|| of (3.21): its multiplier row lambda - [lambda + gamma (u_n - g)]_+ is the
/// Alart-Curnier function with r = gamma.
double residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                const Eigen::VectorXd& lambda, double gamma) {
  return contact_residual(problem, u, lambda, [gamma](double l, double un, double g) {
    return alart_curnier_normal(l, un, g, gamma);
  });
}

} // namespace

ContactSolution PrimalDualActiveSet::solve(const ContactProblem& problem) const {
  const int m = problem.contacts();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(m);
  ContactSolution s;
  s.unknowns = problem.size();

  // (i) x(0) = (0, 0).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.size());
  Eigen::VectorXd lambda = none;
  std::vector<char> previous_active;

  for (int k = 0; k < p_.max_iterations; ++k) {
    // (ii) active and inactive sets from the current iterate.
    const std::vector<char> active = pdas_active_set(problem, u, lambda, p_.gamma);

    // (iii) equilibrium with u_n = g on A (3.31) and lambda = 0 on I (3.32).
    LinearStep step;
    if (!solve_linear_step(problem, active, none, none, u, step)) {
      s.failure = "the linearized system is singular (active set of " +
                  std::to_string(count_active(active)) + " nodes)";
      break;
    }
    const Increment increment = increment_between(stack(step.u, step.reaction, problem.weight),
                                                  stack(u, lambda, problem.weight));
    u = step.u;
    lambda = step.reaction;
    const double r = residual(problem, u, lambda, p_.gamma);
    s.history.push_back({count_active(active), r, increment.relative, increment.norm});

    // (iv) stop when the iterate no longer moves, R vanishes and A(k+1) = A(k).
    if (increment.relative <= p_.eps && r <= p_.eps && active == previous_active) {
      s.converged = true;
      s.active = active;
      break;
    }
    previous_active = active;
  }
  if (!s.converged && s.failure.empty()) s.failure = "no convergence within the iteration limit";
  if (s.active.empty()) s.active = pdas_active_set(problem, u, lambda, p_.gamma);
  s.u = u;
  s.multiplier = lambda;
  return s;
}

} // namespace sig
