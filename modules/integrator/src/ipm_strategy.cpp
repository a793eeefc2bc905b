// The Improved Penalized Method (IPM) of ch. 8.4, (8.30)-(8.32): a Newton continuation in two
// phases over each step,
//   (a) the specific penalty (8.32) everywhere, N = r w p_spe(q_{n-1}, q_n), no wall (8.30);
//   (b) when (a) took a node beyond g: from (a)'s state, the same compliance limited by the
//       unilateral wall at q_n = g (8.31): on the wall the force is the compliance at g,
//       r w p_spe(q_{n-1}, g) ([choice] C14's p_g), plus the wall's reaction Lambda >= 0.
// The wall applies to every node in (b), not only to those (a) took beyond g (the set W of
// (8.31)): a node that (b) would push beyond g is stopped too, so the penetration is bounded by g
// at every node and step. Off the wall the identity (3.53) holds as for the specific penalty;
// the reaction's work -Lambda (g - q_{n-1}) <= 0 is the only dissipation of the frictionless
// method (l.15560). Friction: Coulomb with the whole normal force (or mu1 / mu2 of the
// penetration, (8.3)) in both phases; on the wall q_n = g, where mu1 and mu2 are mu0 (C14).
#include "integrator/strategies.hpp"

#include "solver/contact_bulk.hpp"

namespace sig {

std::vector<ContactLaw> ImprovedPenaltyStrategy::first_laws(const ContactSetting& setting,
                                                            const ContactStepStart& start) const {
  return secant_compliance(setting, start, p_.r, NormalLaw::compliance);
}

ContactStepSolution ImprovedPenaltyStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                                    const ContactStepStart& start) const {
  ContactStepSolution a;
  ContactIterate iterate;
  phase(bulk, first, iterate, a, "phase (a), specific penalty");
  if (!a.converged) return a;
  const Eigen::VectorXd q = bulk.penetration();
  bool beyond = false;
  for (int p = 0; p < first.size(); ++p)
    beyond = beyond || q[p] > first.law[p].depth;
  if (!beyond) return a;

  const ContactSetting b{secant_compliance(first, start, p_.r, NormalLaw::compliance_unilateral),
                         first.weight};
  ContactStepSolution s = a; // phase() adds its iterations to the first phase's
  phase(bulk, b, iterate, s, "phase (b), bounded by g");
  return s;
}

} // namespace sig
