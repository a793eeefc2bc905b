#include "integrator/contact_strategy.hpp"

#include "contact/contact_kernel.hpp"
#include "core/error.hpp"
#include "integrator/strategies.hpp"
#include "solver/contact_bulk.hpp"

namespace sig {

namespace {

/// The predictor already solves the step: the bulk is in equilibrium there and no law gives a
/// force (every node off the obstacle, no secant force from a penetration at the start). Free
/// flight then costs no Newton iteration, and its states stay the scheme's exact ones.
bool predictor_solves_step(const ContactBulk& bulk, const ContactSetting& setting, double eps) {
  const Eigen::VectorXd q_n = bulk.penetration(), q_t = bulk.slip();
  for (int p = 0; p < setting.size(); ++p) {
    const ContactKernel k = contact_kernel(setting.law[p], {q_n[p], q_t[p], 0.0, 0.0}, 1.0, 1.0);
    if (k.normal != 0.0 || k.tangential != 0.0) return false;
  }
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(setting.size());
  return bulk.equilibrium_residual(none, none) <= eps * bulk.force_scale();
}

} // namespace

ContactStepSolution ContactStrategy::solve(ContactBulk& bulk, const ContactSetting& setting,
                                           const ContactStepStart& start) const {
  const int m = setting.size();
  SIG_VERIFY(bulk.contacts() == m && start.penetration.size() == m &&
                 start.normal_velocity.size() == m,
             name() << ": the bulk has " << bulk.contacts() << " contact nodes, the laws " << m
                    << ", the step start " << start.penetration.size());
  const ContactSetting first{first_laws(setting, start), setting.weight};
  if (predictor_solves_step(bulk, first, p_.eps)) {
    ContactStepSolution s;
    s.normal_force = s.tangential_force = Eigen::VectorXd::Zero(m);
    s.normal_status.assign(m, NormalStatus::free);
    s.friction_status.assign(m, FrictionStatus::none);
    s.law = first.law;
    s.converged = true;
    return s;
  }
  return phases(bulk, first, start);
}

void ContactStrategy::phase(ContactBulk& bulk, const ContactSetting& setting,
                            ContactIterate& iterate, ContactStepSolution& solution,
                            const std::string& label) const {
  ContactSolverParameters s;
  s.method = "pdas";
  s.r = p_.gamma;
  s.gamma = p_.gamma;
  s.eps = p_.eps;
  s.max_iterations = p_.max_iterations;
  const std::unique_ptr<ContactMethod> m = make_contact_method(s);
  const ContactNewtonResult r =
      solve_contact(bulk, setting, *m, newton_options(s, setting.law), iterate);
  solution.normal_force = r.normal_force;
  solution.tangential_force = r.tangential_force;
  solution.normal_status = r.normal_status;
  solution.friction_status = r.friction_status;
  solution.law = setting.law;
  solution.converged = r.converged && r.normal_force.allFinite() && r.tangential_force.allFinite();
  solution.iterations += r.iterations();
  if (!solution.converged)
    solution.failure = (label.empty() ? "" : label + ": ") +
                       (r.converged ? "the contact forces are not finite" : r.failure);
}

std::unique_ptr<ContactStrategy> make_contact_strategy(const std::string& name,
                                                       const ContactStrategyParameters& p) {
  const bool needs_r = name == "compliance" || name == "specific-penalty" || name == "ipm";
  SIG_VERIFY(!needs_r || p.r > 0,
             "contact strategy " << name << " needs a foundation stiffness r > 0, got " << p.r);
  SIG_VERIFY(p.max_iterations >= 1, "contact strategy: max_iterations = " << p.max_iterations);
  SIG_VERIFY(p.gamma > 0 && p.eps > 0,
             "contact strategy: gamma = " << p.gamma << " and eps = " << p.eps << " must be > 0");
  if (name == "signorini") return std::make_unique<SignoriniStrategy>(p);
  if (name == "compliance") return std::make_unique<ComplianceStrategy>(p);
  if (name == "specific-penalty") return std::make_unique<SpecificPenaltyStrategy>(p);
  if (name == "two-step") return std::make_unique<TwoStepStrategy>(p);
  if (name == "ipm") return std::make_unique<ImprovedPenaltyStrategy>(p);
  SIG_VERIFY(false,
             "unknown contact strategy '" << name << "' (choose " << contact_strategy_names << ")");
  return nullptr;
}

double interface_energy(const std::vector<ContactLaw>& laws, const Eigen::VectorXd& weight,
                        const Eigen::VectorXd& penetration) {
  double sum = 0;
  for (std::size_t p = 0; p < laws.size(); ++p) {
    const auto i = static_cast<Eigen::Index>(p);
    sum += weight[i] * compliance_energy(laws[p], penetration[i]);
  }
  return sum;
}

std::vector<ContactLaw> secant_compliance(const ContactSetting& setting,
                                          const ContactStepStart& start, double r,
                                          NormalLaw normal) {
  std::vector<ContactLaw> laws = setting.law;
  for (std::size_t p = 0; p < laws.size(); ++p) {
    laws[p].normal = normal;
    laws[p].cn = r;
    laws[p].c3 = std::numeric_limits<double>::infinity();
    laws[p].secant = true;
    laws[p].previous = start.penetration[static_cast<Eigen::Index>(p)];
  }
  return laws;
}

} // namespace sig
