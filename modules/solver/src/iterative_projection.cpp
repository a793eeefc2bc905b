// Iterative projection, thesis section 7.2, (7.16)-(7.22): the fixed point
// u_n = -[-u_n - c lambda]_+ (7.18) solved with an implicit scheme on Gamma3 (7.19). Active
// nodes get u_n = g (7.21); inactive nodes the Robin condition u_n(k+1) = u_n(k) + c lambda(k+1)
// (7.22), with lambda the pressure: the nodal force is w (u_n(k+1) - u_n(k)) / c, a spring w / c
// on the diagonal and w u_n(k) / c on the right side. A small c holds the inactive nodes back,
// hence more iterations (Table 7.1).
//
// In step (ii) the multiplier of a node the previous iteration left inactive is taken as zero,
// its contact multiplier by Signorini: the Robin force there is the relaxation of the implicit
// scheme (7.19), not a contact force, and vanishes at convergence. Feeding it to (ii) instead
// tests the extrapolation u_n(k) + (u_n(k) - u_n(k-1)) for every c and costs two or three
// iterations more than Table 7.1 reports (measured at N = 128: 16/11/10/9/9 against
// 12/9/8/7/7 for c = 1 ... 1e4; thesis 11/8/7/7/7).
#include "contact/complementarity.hpp"
#include "solver/methods.hpp"

namespace sig {

namespace {

/// Step (ii): A(k+1) = { p : (u_n,p - g_p) + c lambda_p >= 0 }.
std::vector<char> projection_active_set(const ContactProblem& problem, const Eigen::VectorXd& u,
                                        const Eigen::VectorXd& lambda, double c) {
  return active_set(problem, u, lambda, [c](double l, double un, double g) {
    return projection_is_active(l, un, g, c);
  });
}

/// ||R*(u, lambda)|| of (7.23); the projection rows are divided by c to read as forces.
double residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                const Eigen::VectorXd& lambda, double c) {
  return contact_residual(problem, u, lambda, [c](double l, double un, double g) {
    return projection_residual(l, un, g, c) / c;
  });
}

} // namespace

ContactSolution IterativeProjection::solve(const ContactProblem& problem) const {
  const int m = problem.contacts();
  const double c = p_.c;
  ContactSolution s;
  s.unknowns = problem.size();

  // (i) x(0) = (0, 0).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.size());
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  std::vector<char> previous_active;

  for (int k = 0; k < p_.max_iterations; ++k) {
    // (ii) active and inactive sets, from the contact multipliers (zero off the active set).
    Eigen::VectorXd contact_multiplier = lambda;
    for (int p = 0; p < m && !previous_active.empty(); ++p)
      if (!previous_active[p]) contact_multiplier[p] = 0;
    const std::vector<char> active = projection_active_set(problem, u, contact_multiplier, c);

    // (iii) (7.20) with u_n = g on A (7.21) and the Robin condition (7.22) on I.
    const Eigen::VectorXd un_old = problem.normal_part(u);
    Eigen::VectorXd robin_stiffness = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd robin_load = Eigen::VectorXd::Zero(m);
    for (int p = 0; p < m; ++p)
      if (!active[p]) {
        robin_stiffness[p] = problem.weight[p] / c;
        robin_load[p] = problem.weight[p] * un_old[p] / c;
      }
    LinearStep step;
    if (!solve_linear_step(problem, active, robin_stiffness, robin_load, u, step)) {
      s.failure = "the linearized system is singular (active set of " +
                  std::to_string(count_active(active)) + " nodes)";
      break;
    }
    Eigen::VectorXd lambda_new = step.reaction;
    const Eigen::VectorXd un = problem.normal_part(step.u);
    for (int p = 0; p < m; ++p)
      if (!active[p]) lambda_new[p] = problem.weight[p] * (un[p] - un_old[p]) / c;

    const Increment increment = increment_between(stack(step.u, lambda_new, problem.weight),
                                                  stack(u, lambda, problem.weight));
    u = step.u;
    lambda = lambda_new;
    const double r = residual(problem, u, lambda, c);
    s.history.push_back({count_active(active), r, increment.relative, increment.norm});

    // (iv)
    if (increment.relative <= p_.eps && r <= p_.eps && active == previous_active) {
      s.converged = true;
      s.active = active;
      break;
    }
    previous_active = active;
  }
  if (!s.converged && s.failure.empty()) s.failure = "no convergence within the iteration limit";
  if (s.active.empty()) s.active = projection_active_set(problem, u, lambda, c);
  s.u = u;
  s.multiplier = lambda;
  return s;
}

} // namespace sig
