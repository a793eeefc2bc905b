#pragma once
// The implicit midpoint rule (3.39) for linear elastodynamics:
//     M (v_{n+1} - v_n) / k + K (u_{n+1} + u_n) / 2 = f(t_{n+1/2}),
//     (u_{n+1} - u_n) / k = (v_{n+1} + v_n) / 2,
// i.e. delta u_{n+1} = -delta u_n + (2 / k)(u_{n+1} - u_n) in the thesis' notation. Taking the
// product of the first line with u_{n+1} - u_n = k (v_{n+1} + v_n) / 2 gives, for symmetric M
// and K, the exact discrete energy balance
//     E_{n+1} - E_n = f(t_{n+1/2}) . (u_{n+1} - u_n),   E = 1/2 v.M v + 1/2 u.K u,
// so without load the energy is conserved to round-off at any step size.
#include "integrator/time_scheme.hpp"

namespace sig {

class ImplicitMidpoint final : public TimeScheme {
public:
  ImplicitMidpoint(Elastodynamics problem, double k, const std::string& linear_solver = "cholmod");

  /// f(t + k / 2).
  Eigen::VectorXd step_load(double t) const override;
  std::string name() const override { return "midpoint"; }
};

} // namespace sig
