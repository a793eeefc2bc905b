#include "integrator/contact_strategy.hpp"

#include "contact/contact_kernel.hpp"
#include "core/error.hpp"
#include "integrator/strategies.hpp"
#include "solver/contact_bulk.hpp"

namespace sig {

namespace {

/// Whether the law of node p gives it a force at its penetration q_n and slip (the bulk's flat
/// slips q_t, d - 1 per node) without multipliers: in 3D the slip is the node's tangent-plane
/// vector.
template <int d>
bool gives_force(const ContactLaw& law, double q_n, const Eigen::VectorXd& q_t, int p) {
  NodeVariablesIn<d> x;
  x.q_n = q_n;
  if constexpr (d == 2)
    x.q_t = q_t[p];
  else
    x.q_t = q_t.segment<d - 1>((d - 1) * p);
  const ContactKernelIn<d> k = contact_kernel(law, x, 1.0, 1.0);
  if constexpr (d == 2)
    return k.normal != 0.0 || k.tangential != 0.0;
  else
    return k.normal != 0.0 || !k.tangential.isZero();
}

} // namespace

bool predictor_solves_step(const ContactBulk& bulk, const ContactSetting& setting, double eps) {
  const Eigen::VectorXd q_n = bulk.penetration(), q_t = bulk.slip();
  const bool plane = bulk.has_tangential() && bulk.tangents() == 2;
  for (int p = 0; p < setting.size(); ++p)
    if (plane ? gives_force<3>(setting.law[p], q_n[p], q_t, p)
              : gives_force<2>(setting.law[p], q_n[p], q_t, p))
      return false;
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(setting.size());
  const Eigen::VectorXd no_tangential = Eigen::VectorXd::Zero(q_t.size());
  return bulk.equilibrium_residual(none, no_tangential) <= eps * bulk.force_scale();
}

ContactStepSolution ContactStrategy::free_solution(const ContactSetting& first,
                                                   Eigen::Index slips) {
  const int m = first.size();
  ContactStepSolution s;
  s.normal_force = Eigen::VectorXd::Zero(m);
  s.tangential_force = Eigen::VectorXd::Zero(slips); // d - 1 per node
  s.normal_status.assign(m, NormalStatus::free);
  s.friction_status.assign(m, FrictionStatus::none);
  s.law = first.law;
  s.converged = true;
  return s;
}

ContactStepSolution ContactStrategy::solve(ContactBulk& bulk, const ContactSetting& setting,
                                           const ContactStepStart& start) const {
  const int m = setting.size();
  SIG_VERIFY(bulk.contacts() == m && start.penetration.size() == m &&
                 start.normal_velocity.size() == m,
             name() << ": the bulk has " << bulk.contacts() << " contact nodes, the laws " << m
                    << ", the step start " << start.penetration.size());
  const ContactSetting first{first_laws(setting, start), setting.weight};
  if (predictor_solves_step(bulk, first, p_.eps)) return free_solution(first, bulk.slip().size());
  return phases(bulk, first, start);
}

ContactStepSolution ContactStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                            const ContactStepStart&) const {
  ContactStepSolution s;
  ContactIterate iterate;
  phase(bulk, first, iterate, s);
  return s;
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
  const ContactNewtonResult r = solve_contact(bulk, setting, *m, newton_options(s), iterate);
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

namespace {

/// A strategy of the card: its traits and its constructor.
struct StrategyEntry {
  const char* name;
  ContactStrategyTraits traits;
  std::unique_ptr<ContactStrategy> (*make)(const ContactStrategyParameters&);
};

template <class Strategy>
std::unique_ptr<ContactStrategy> construct(const ContactStrategyParameters& p) {
  return std::make_unique<Strategy>(p);
}

/// The strategy called `name`: the one place a strategy's name is read.
const StrategyEntry& strategy_named(const std::string& name) {
  static const StrategyEntry entries[] = {
      {"signorini", {}, construct<SignoriniStrategy>},
      {"compliance", {.needs_r = true, .has_wall = false}, construct<ComplianceStrategy>},
      {"specific-penalty",
       {.needs_r = true, .has_wall = false},
       construct<SpecificPenaltyStrategy>},
      {"two-step", {.has_persistency = true}, construct<TwoStepStrategy>},
      {"ipm", {.needs_r = true}, construct<ImprovedPenaltyStrategy>}};
  for (const StrategyEntry& entry : entries)
    if (name == entry.name) return entry;
  SIG_VERIFY(false,
             "unknown contact strategy '" << name << "' (choose " << contact_strategy_names << ")");
  return entries[0];
}

} // namespace

std::unique_ptr<ContactStrategy> make_contact_strategy(const std::string& name,
                                                       const ContactStrategyParameters& p) {
  const StrategyEntry& strategy = strategy_named(name);
  SIG_VERIFY(!strategy.traits.needs_r || p.r > 0,
             "contact strategy " << name << " needs a foundation stiffness r > 0, got " << p.r);
  SIG_VERIFY(p.max_iterations >= 1, "contact strategy: max_iterations = " << p.max_iterations);
  SIG_VERIFY(p.gamma > 0 && p.eps > 0,
             "contact strategy: gamma = " << p.gamma << " and eps = " << p.eps << " must be > 0");
  return strategy.make(p);
}

ContactStrategyTraits contact_strategy_traits(const std::string& name) {
  return strategy_named(name).traits;
}

ContactRecord contact_record(const ContactStepSolution& solution) {
  ContactRecord r;
  r.normal_force = solution.normal_force;
  r.tangential_force = solution.tangential_force;
  r.normal_status = solution.normal_status;
  r.friction_status = solution.friction_status;
  return r;
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
