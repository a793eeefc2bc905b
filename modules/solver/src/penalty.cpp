// Penalty method, thesis Remark 3.2: the augmented Lagrangian with its multipliers set to zero,
// so the foundation acts as a bed of springs of stiffness r per unit area (Winkler) and the
// contact pressure is r [u_n - g]_+. The result penetrates by pressure / r; a larger r
// penetrates less but conditions the system worse.
// Solved by Newton's method on K u + E^T r [u_n - g]_+ = f.
#include "contact/complementarity.hpp"
#include "solver/methods.hpp"

namespace sig {

namespace {

Eigen::VectorXd contact_force(const ContactProblem& problem, const Eigen::VectorXd& u, double r) {
  const Eigen::VectorXd un = problem.normal_part(u);
  Eigen::VectorXd force(problem.contacts());
  for (int p = 0; p < problem.contacts(); ++p)
    force[p] = problem.weight[p] * penalty_force(un[p], problem.gap[p], r);
  return force;
}

} // namespace

ContactSolution Penalty::solve(const ContactProblem& problem) const {
  const int m = problem.contacts();
  const double r = p_.r;
  ContactSolution s;
  s.unknowns = problem.size();

  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.size());
  std::vector<char> previous_active;
  const std::vector<char> nothing_imposed(m, 0);

  for (int k = 0; k < p_.max_iterations; ++k) {
    // Newton on the piecewise-linear penalty force: the spring r acts on nodes at or beyond the
    // obstacle (derivative of [.]_+ taken as 1 at the kink).
    const Eigen::VectorXd un = problem.normal_part(u);
    std::vector<char> active(m);
    Eigen::VectorXd spring = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd spring_load = Eigen::VectorXd::Zero(m);
    for (int p = 0; p < m; ++p) {
      active[p] = d_penalty_force(un[p], problem.gap[p], r) > 0;
      if (active[p]) {
        spring[p] = problem.weight[p] * r;
        spring_load[p] = problem.weight[p] * r * problem.gap[p];
      }
    }
    LinearStep step;
    if (!solve_linear_step(problem, nothing_imposed, spring, spring_load, u, step)) {
      s.failure = "the tangent is singular (" + std::to_string(count_active(active)) +
                  " nodes on the foundation)";
      break;
    }
    const Increment increment = increment_between(step.u, u);
    u = step.u;
    const double res = equilibrium_residual(problem, u, contact_force(problem, u, r));
    s.history.push_back({count_active(active), res, increment.relative, increment.norm});

    if (increment.relative <= p_.eps && res <= p_.eps && active == previous_active) {
      s.converged = true;
      break;
    }
    previous_active = active;
  }
  if (!s.converged && s.failure.empty()) s.failure = "no convergence within the iteration limit";
  s.u = u;
  s.multiplier = contact_force(problem, u, r);
  s.active.resize(m);
  for (int p = 0; p < m; ++p)
    s.active[p] = s.multiplier[p] > 0;
  return s;
}

} // namespace sig
