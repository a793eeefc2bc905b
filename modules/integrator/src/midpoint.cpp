#include "integrator/midpoint.hpp"

#include <utility>

namespace sig {

ImplicitMidpoint::ImplicitMidpoint(Elastodynamics problem, double k,
                                   const std::string& linear_solver)
    : TimeScheme(std::move(problem), k, linear_solver) {}

Eigen::VectorXd ImplicitMidpoint::step_load(double t) const {
  return problem().load_at(t + 0.5 * time_step());
}

// With d = u_{n+1} - u_n the kinematic line gives v_{n+1} = (2 / k) d - v_n; in the balance
// line, M (v_{n+1} - v_n) / k = (2 / k^2) M d - (2 / k) M v_n and K (u_{n+1} + u_n) / 2 =
// K d / 2 + K u_n, so, times 2,
//     (K + (4 / k^2) M) d = 2 f(t_{n+1/2}) - 2 K u_n + (4 / k) M v_n.
// Solving for the increment d rather than for u_{n+1} keeps the right side free of the large
// (4 / k^2) M u_n term and its cancellation.
DynamicState ImplicitMidpoint::advance(const DynamicState& state) const {
  check_state(state);
  const double k = time_step();
  const Elastodynamics& p = problem();
  const Eigen::VectorXd rhs =
      2.0 * step_load(state.time) - 2.0 * (p.K * state.u) + (4.0 / k) * (p.M * state.v);
  const Eigen::VectorXd d = solve_step_operator(rhs);
  DynamicState next;
  next.time = state.time + k;
  next.u = state.u + d;
  next.v = (2.0 / k) * d - state.v;
  return next;
}

} // namespace sig
