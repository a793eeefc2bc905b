#include "integrator/newmark.hpp"

#include <utility>

namespace sig {

NewmarkAverageAcceleration::NewmarkAverageAcceleration(Elastodynamics problem, double k,
                                                       const std::string& linear_solver)
    : TimeScheme(std::move(problem), k, linear_solver) {}

Eigen::VectorXd NewmarkAverageAcceleration::step_load(double t) const {
  return 0.5 * (problem().load_at(t) + problem().load_at(t + time_step()));
}

// Multiplying the displacement update by (4 / k^2) M and inserting the equilibria M a_n = f_n
// - K u_n and M a_{n+1} = f_{n+1} - K (u_n + d) gives, for the increment d = u_{n+1} - u_n,
//     (K + (4 / k^2) M) d = f_{n+1} - K u_n + M a_n + (4 / k) M v_n.
// Solving for d rather than for u_{n+1} avoids the (4 / k^2) M u_n term, whose rounding, once
// differenced into v_{n+1} = (2 / k) d - v_n, grows with the distance the body has travelled.
DynamicState NewmarkAverageAcceleration::advance(const DynamicState& state) const {
  check_state(state);
  const double k = time_step();
  const Elastodynamics& p = problem();
  const Eigen::VectorXd K_u = p.K * state.u;
  const Eigen::VectorXd inertial_force = p.load_at(state.time) - K_u; // M a_n
  const Eigen::VectorXd rhs =
      p.load_at(state.time + k) - K_u + inertial_force + (4.0 / k) * (p.M * state.v);
  const Eigen::VectorXd d = solve_step_operator(rhs);
  DynamicState next;
  next.time = state.time + k;
  next.u = state.u + d;
  next.v = (2.0 / k) * d - state.v;
  return next;
}

} // namespace sig
