#include "solver/contact_solver.hpp"

#include "core/error.hpp"
#include "solver/methods.hpp"

namespace sig {

std::unique_ptr<ContactSolver> make_contact_solver(const ContactSolverParameters& parameters) {
  const std::string& m = parameters.method;
  if (m == "alm") return std::make_unique<AugmentedLagrangian>(parameters);
  if (m == "penalty") return std::make_unique<Penalty>(parameters);
  if (m == "pdas") return std::make_unique<PrimalDualActiveSet>(parameters);
  if (m == "projection") return std::make_unique<IterativeProjection>(parameters);
  SIG_VERIFY(false, "unknown contact method '" << m << "'; known: alm penalty pdas projection");
  return nullptr;
}

double equilibrium_residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                            const Eigen::VectorXd& multiplier) {
  Eigen::VectorXd r = problem.K * u - problem.f;
  for (int p = 0; p < problem.contacts(); ++p)
    r[problem.normal_dof[p]] += multiplier[p];
  return r.norm() / std::max(problem.f.norm(), 1e-300);
}

Increment increment_between(const Eigen::VectorXd& now, const Eigen::VectorXd& before) {
  const double norm = (now - before).norm();
  return {norm, norm / std::max(now.norm(), 1e-300)};
}

Eigen::VectorXd stack(const Eigen::VectorXd& u, const Eigen::VectorXd& lambda,
                      const Eigen::VectorXd& weight) {
  Eigen::VectorXd x(u.size() + lambda.size());
  x << u, lambda.cwiseQuotient(weight);
  return x;
}

int count_active(const std::vector<char>& active) {
  int n = 0;
  for (char a : active)
    n += a ? 1 : 0;
  return n;
}

} // namespace sig
