#pragma once
// The quasistatic march of ch. 5 for a Kelvin-Voigt body with memory (material/kelvin_voigt.hpp):
// backward Euler in velocity (5.62)-(5.64) with the trapezoidal memory (5.60)-(5.61). The unknown
// of step n is the velocity w_n = (u_n - u_{n-1}) / k of the free dofs; with K_A the viscosity's
// matrix, K_B the elastic stiffness and K_m the stiffness of the memory term exp(-beta_m t) KK_m,
//
//   S   = K_A + k K_B + (k / 2) sum_m K_m                                (constant)
//   b_n = f(t_n) - K_B u_{n-1} - k sum_m K_m P_m,n
//   u_n = u_{n-1} + k w_n,   P_m,n+1 = exp(-beta_m k) (P_m,n + w_n)      (integrator/memory.hpp)
//
// (ALGORITHMS.md 2.2). No mass, no density. [choices, ALGORITHMS.md C8] u_n by backward Euler,
// not by the trapezoidal rule (5.66) names; w_0 = 0 (the memory's first term; (5.61) needs it and
// the thesis never defines it); the memory integrand eps(du/dt(s)). f(t) = f + change(t) holds
// the ramped and moving loads (assembly/time_loads.hpp). Without viscosity and memory
// (eta1 = eta2 = 0, K = 0) a step is k K_B w_n = f(t_n) - K_B u_{n-1}: the static solve
// K_B u_n = f(t_n) at every step.
#include "integrator/linear_contact_march.hpp"
#include "integrator/memory.hpp"
#include "integrator/viscoelastic_problem.hpp"
#include "solver/symmetric_product.hpp"

#include <vector>

namespace sig {

class QuasistaticKelvinVoigt final : public VelocityScheme {
public:
  /// The stiffness, viscosity and memory terms of `problem` (C and memory empty for a purely
  /// elastic body; no mass) and its loads; k > 0; u0 the initial displacement (empty: 0).
  QuasistaticKelvinVoigt(ViscoelasticProblem problem, double k, Eigen::VectorXd u0 = {});

  std::string name() const override { return "quasistatic"; }
  double time_step() const override { return k_; }
  const Eigen::SparseMatrix<double>& step_matrix() const override { return S_; }
  bool rank_rows() const override { return rank_rows_; }
  Eigen::VectorXd right_side(int n) const override;
  void accept(int n, const Eigen::VectorXd& w) override;
  const Eigen::VectorXd& displacement() const override { return u_; }

private:
  LoadHistory load_;
  double k_;
  Eigen::SparseMatrix<double> S_;
  bool rank_rows_ = false;
  SymmetricProduct elastic_;               ///< K_B u
  std::vector<SymmetricProduct> memory_K_; ///< the K_m's products
  std::vector<ExponentialMemory> memory_;  ///< P_m
  Eigen::VectorXd u_;
};

} // namespace sig
