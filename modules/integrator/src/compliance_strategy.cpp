// Normal compliance at the end of the step, N = r w [q_n]_+ (1.24): the foundation a bed of
// springs of stiffness r per unit area, no wall (the thesis's "g = 1000"). The force is evaluated
// at t_n only, so its work over a step is not the change of the springs' energy: the scheme gains
// or loses energy at the impact depending on the step.
#include "integrator/strategies.hpp"

namespace sig {

std::vector<ContactLaw> ComplianceStrategy::first_laws(const ContactSetting& setting,
                                                       const ContactStepStart&) const {
  std::vector<ContactLaw> laws = setting.law;
  for (ContactLaw& law : laws) {
    law.normal = NormalLaw::compliance;
    law.cn = p_.r;
  }
  return laws;
}

ContactStepSolution ComplianceStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                               const ContactStepStart&) const {
  ContactStepSolution s;
  ContactIterate iterate;
  phase(bulk, first, iterate, s);
  return s;
}

} // namespace sig
