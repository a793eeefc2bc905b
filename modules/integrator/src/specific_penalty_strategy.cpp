// The specific penalty of [62], thesis (3.48)-(3.53) and (8.32): the compliance r w [q]_+ as its
// secant over the step, N = r w p_spe(q_{n-1}, q_n) (contact/complementarity.hpp). Its work over
// the step, -r w ([q_n]_+^2 - [q_{n-1}]_+^2) / 2, is the change of the foundation's energy, so the
// midpoint rule conserves E + (r / 2) sum w [q]_+^2 exactly (3.53); the penetration is not zero
// (0.0034 m in scene 8a, 0.058 m in 8b). The compliance has no wall, hence no multiplier; friction
// is exact Coulomb by the tangential multiplier of PDAS, as in IPM ([choice]: the thesis's garbled
// stick law "gamma_tau = r delta u_tau" suggests a penalty T = proj(r Delta, mu N), ALGORITHMS.md
// 4.3 (A); with r = 1e9 Pa/m the semi-smooth Newton method then cycles between the two slip
// directions of a node that should stick, measured on the Scene 8b ring).
#include "integrator/strategies.hpp"

namespace sig {

std::vector<ContactLaw> SpecificPenaltyStrategy::first_laws(const ContactSetting& setting,
                                                            const ContactStepStart& start) const {
  return secant_compliance(setting, start, p_.r, NormalLaw::compliance);
}

ContactStepSolution SpecificPenaltyStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                                    const ContactStepStart&) const {
  ContactStepSolution s;
  ContactIterate iterate;
  phase(bulk, first, iterate, s);
  return s;
}

} // namespace sig
