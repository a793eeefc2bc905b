// The specific penalty of [62], thesis (3.48)-(3.53) and (8.32): the compliance r w [q]_+ as its
// secant over the step, N = r w p_spe(q_{n-1}, q_n) (contact/complementarity.hpp). Its work over
// the step, -r w ([q_n]_+^2 - [q_{n-1}]_+^2) / 2, is the change of the foundation's energy, so the
// midpoint rule conserves E + (r / 2) sum w [q]_+^2 exactly (3.53); the penetration is not zero
// (0.0034 m in scene 8a, 0.058 m in 8b). Friction by penalty ([choice] ALGORITHMS.md 4.3 (A), the
// thesis's garbled "gamma_tau = r delta u_tau" on stick): T = proj(r Delta, mu N), Delta the slip
// over the step, which only dissipates (T Delta >= 0). Both are the penalty method of the driver
// (Remark 3.2) with r.
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
  phase(bulk, first, "penalty", iterate, s);
  return s;
}

} // namespace sig
