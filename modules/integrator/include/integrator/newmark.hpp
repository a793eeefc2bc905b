#pragma once
// Newmark's average acceleration scheme (beta = 1/4, gamma = 1/2, the trapezoidal rule), the
// classical reference of ch. 3.3:
//     u_{n+1} = u_n + k v_n + (k^2 / 4)(a_n + a_{n+1}),
//     v_{n+1} = v_n + (k / 2)(a_n + a_{n+1}),
//     M a_{n+1} + K u_{n+1} = f(t_{n+1}).
// Written for the increment d = u_{n+1} - u_n (newmark.cpp) it reads
//     (K + (4 / k^2) M) d = f_{n+1} - K u_n + M a_n + (4 / k) M v_n,
// and the inertial force M a_n = f_n - K u_n is known from the equilibrium at t_n (at t_0 it
// defines a_0), so the scheme never inverts M: it runs with a singular mass (EMM) too. With
// gamma = 2 beta the velocity update needs no acceleration either: v_{n+1} = (2 / k) d - v_n. For a
// linear problem this is the midpoint rule with the load (f_n + f_{n+1}) / 2 in place of
// f(t_{n+1/2}): both coincide for a load affine in time.
#include "integrator/time_scheme.hpp"

namespace sig {

class NewmarkAverageAcceleration final : public TimeScheme {
public:
  NewmarkAverageAcceleration(Elastodynamics problem, double k,
                             const std::string& linear_solver = "cholmod");

  /// (f(t) + f(t + k)) / 2.
  Eigen::VectorXd step_load(double t) const override;
  std::string name() const override { return "newmark"; }
};

} // namespace sig
