#include "integrator/contact_strategy.hpp"

#include "core/error.hpp"
#include "integrator/dynamic_contact.hpp"
#include "integrator/strategies.hpp"
#include "solver/condensed_contact.hpp"

#include <numeric>
#include <utility>

namespace sig {

namespace {

/// Tolerance of the static methods' test (iv). Their iterations are exact linear solves on a
/// fixed active set, so once the set repeats the iterate is the answer to rounding; the test
/// only has to see the set repeat.
constexpr double kStaticTolerance = 1e-9;

} // namespace

std::unique_ptr<ContactStrategy> make_contact_strategy(const std::string& name,
                                                       const ContactStrategyParameters& p) {
  const bool needs_r = name == "compliance" || name == "specific-penalty" || name == "ipm";
  SIG_VERIFY(!needs_r || p.r > 0,
             "contact strategy " << name << " needs a foundation stiffness r > 0, got " << p.r);
  SIG_VERIFY(p.max_iterations >= 1, "contact strategy: max_iterations = " << p.max_iterations);
  if (name == "signorini") return std::make_unique<SignoriniStrategy>(p);
  if (name == "compliance") return std::make_unique<ComplianceStrategy>(p);
  if (name == "specific-penalty") return std::make_unique<SpecificPenaltyStrategy>(p);
  if (name == "two-step") return std::make_unique<TwoStepStrategy>(p);
  if (name == "ipm") return std::make_unique<ImprovedPenaltyStrategy>(p);
  SIG_VERIFY(false,
             "unknown contact strategy '" << name << "' (choose " << contact_strategy_names << ")");
  return nullptr;
}

ContactSolverParameters static_method(const std::string& method,
                                      const ContactStrategyParameters& p) {
  ContactSolverParameters s;
  s.method = method;
  s.r = p.r;
  s.eps = kStaticTolerance;
  s.max_iterations = p.max_iterations;
  return s;
}

ContactStepSolution
solve_with_static_method(const NormalStep& step, const ContactBoundary& boundary,
                         const std::vector<int>& elements, const Eigen::VectorXd& gap,
                         const ContactSolverParameters& method, std::vector<char>* active) {
  // The condensed step as a static problem: S = A, f = A x_free, equilibrium A x + lambda = f,
  // Signorini with the bound `gap` on the elements.
  CondensedProblem problem;
  problem.S = step.A;
  problem.f = step.A * step.x_free;
  problem.normal_dof = elements;
  problem.gap.resize(static_cast<Eigen::Index>(elements.size()));
  ContactSetting setting;
  setting.weight.resize(problem.gap.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    problem.gap[static_cast<Eigen::Index>(e)] = gap[elements[e]];
    setting.weight[static_cast<Eigen::Index>(e)] = boundary.weight[elements[e]];
  }
  setting.law.assign(elements.size(), ContactLaw{});
  const ContactNewtonResult c =
      solve_condensed_contact(std::move(problem), setting, method).contact;
  ContactStepSolution s;
  s.lambda = Eigen::VectorXd::Zero(boundary.size());
  if (active) active->assign(boundary.size(), 0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    s.lambda[elements[e]] = c.normal_force[static_cast<Eigen::Index>(e)];
    if (active) (*active)[elements[e]] = c.normal_status[e] != NormalStatus::free;
  }
  s.converged = c.converged && s.lambda.allFinite();
  s.failure =
      c.converged && !s.lambda.allFinite() ? "the contact forces are not finite" : c.failure;
  s.iterations = c.iterations();
  return s;
}

ContactStepSolution solve_unilateral(const NormalStep& step, const ContactBoundary& boundary,
                                     const Eigen::VectorXd& gap,
                                     const ContactSolverParameters& method,
                                     std::vector<char>* active) {
  if (!any_beyond(step.x_free, gap)) {
    ContactStepSolution s;
    s.lambda = Eigen::VectorXd::Zero(boundary.size());
    s.converged = true;
    if (active) active->assign(boundary.size(), 0);
    return s;
  }
  std::vector<int> all(boundary.size());
  std::iota(all.begin(), all.end(), 0);
  return solve_with_static_method(step, boundary, all, gap, method, active);
}

bool any_beyond(const Eigen::VectorXd& x, const Eigen::VectorXd& limit) {
  return ((x - limit).array() > 0).any();
}

} // namespace sig
