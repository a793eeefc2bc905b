// Classical Signorini at the end of the step: q_n <= g, N >= 0, N (q_n - g) = 0 (the CONT law),
// by the primal-dual active set method. A node that arrives at the obstacle is stopped there
// within one step, and the forces at t_n do the work -N (q_n - q_{n-1}) <= 0: the scheme loses the
// normal kinetic energy of the nodes that hit (the dissipation of Fig 8.3) and keeps the
// penetration at g.
#include "integrator/strategies.hpp"

namespace sig {

std::vector<ContactLaw> SignoriniStrategy::first_laws(const ContactSetting& setting,
                                                      const ContactStepStart&) const {
  return setting.law;
}

ContactStepSolution SignoriniStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                              const ContactStepStart&) const {
  ContactStepSolution s;
  ContactIterate iterate;
  phase(bulk, first, iterate, s);
  return s;
}

} // namespace sig
