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
//     (K + (4 / k^2) M) d = 2 f(t_{n+1/2}) - 2 K u_n + (4 / k) M v_n,
// the step of TimeScheme::advance with f_bar = f(t_{n+1/2}).

} // namespace sig
