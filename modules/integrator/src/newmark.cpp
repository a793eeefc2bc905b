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
//     (K + (4 / k^2) M) d = f_{n+1} - K u_n + M a_n + (4 / k) M v_n
//                         = (f_n + f_{n+1}) - 2 K u_n + (4 / k) M v_n,
// the step of TimeScheme::advance with f_bar = (f_n + f_{n+1}) / 2: for a linear problem,
// Newmark's average acceleration is the midpoint rule with the averaged load. M is never
// inverted, so a singular mass (EMM) is fine.

} // namespace sig
