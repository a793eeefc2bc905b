#pragma once
// The four contact methods (one file each in src/) and the small pieces their loops share.
#include "solver/contact_solver.hpp"

#include <algorithm>
#include <cmath>

namespace sig {

class AugmentedLagrangian final : public ContactSolver {
public:
  explicit AugmentedLagrangian(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "alm"; }

private:
  ContactSolverParameters p_;
};

class Penalty final : public ContactSolver {
public:
  explicit Penalty(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "penalty"; }

private:
  ContactSolverParameters p_;
};

class PrimalDualActiveSet final : public ContactSolver {
public:
  explicit PrimalDualActiveSet(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "pdas"; }

private:
  ContactSolverParameters p_;
};

class IterativeProjection final : public ContactSolver {
public:
  explicit IterativeProjection(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "projection"; }

private:
  ContactSolverParameters p_;
};

/// Step (ii) of the active-set methods: the elements p where is_active(pressure_p, u_n,p, g_p).
template <class Test>
std::vector<char> active_set(const ContactProblem& problem, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& lambda, Test is_active) {
  const Eigen::VectorXd un = problem.normal_part(u);
  std::vector<char> active(problem.contacts());
  for (int p = 0; p < problem.contacts(); ++p)
    active[p] = is_active(lambda[p] / problem.weight[p], un[p], problem.gap[p]);
  return active;
}

/// ||R(u, lambda)|| relative to the load, R = (equilibrium, complementarity(pressure_p, u_n,p,
/// g_p) per element), the complementarity rows (pressures) times the weights to read as forces.
template <class Complementarity>
double contact_residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                        const Eigen::VectorXd& lambda, Complementarity complementarity) {
  const Eigen::VectorXd un = problem.normal_part(u);
  double sum = 0;
  for (int p = 0; p < problem.contacts(); ++p)
    sum += std::pow(problem.weight[p] *
                        complementarity(lambda[p] / problem.weight[p], un[p], problem.gap[p]),
                    2);
  return std::hypot(equilibrium_residual(problem, u, lambda),
                    std::sqrt(sum) / std::max(problem.f.norm(), 1e-300));
}

/// x = (u, lambda / w), the Newton vector of test (iv), with the multipliers as pressures (the
/// thesis's densities): nodal forces would shrink with h and weigh less on finer meshes.
Eigen::VectorXd stack(const Eigen::VectorXd& u, const Eigen::VectorXd& lambda,
                      const Eigen::VectorXd& weight);
int count_active(const std::vector<char>& active);

} // namespace sig
