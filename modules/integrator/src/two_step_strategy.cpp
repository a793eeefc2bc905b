// The two-step strategy of [13], thesis 3.3.3. Kuhn-Tucker and persistency conditions cannot
// hold together on one step (the problem would be over-constrained), so they are imposed one
// after the other, (b) continuing the Newton method of (a):
//   (a) the CONT law (Signorini) at t_n: it finds the contact statuses;
//   (b) a node (a) left free carries no force; a node (a) left in contact gets the persistency
//       condition (1.31) on its normal velocity at t_n, v_n <= 0, N >= 0, N v_n = 0, with friction
//       as in (a).
// The velocity is the midpoint velocity (3.39) by default ([choice] C15): v_n = -v_{n-1} + (2 / k)
// (q_n - q_{n-1}), so (b) is Signorini with the wall at q_{n-1} + k v_{n-1} / 2, and a node
// arriving at speed v may sink k v / 2 (the thesis's 0.0051 m in scene 8a, for k v / 2 = 0.005).
// Its forces then do the work -N k v_{n-1} / 2 at the arrival step. With persistency=increment
// the wall is q_{n-1} itself: every force of (b) is workless (the energy identity (3.46) exact),
// but a node never moves closer than it was at t_{n-1} and the penetration is nil.
// The unilateral condition is no longer exact at t_n: a node free in (a) is free in (b).
#include "integrator/strategies.hpp"

namespace sig {

std::vector<ContactLaw> TwoStepStrategy::first_laws(const ContactSetting& setting,
                                                    const ContactStepStart&) const {
  return setting.law;
}

ContactStepSolution TwoStepStrategy::phases(ContactBulk& bulk, const ContactSetting& first,
                                            const ContactStepStart& start) const {
  ContactStepSolution a;
  ContactIterate iterate;
  phase(bulk, first, iterate, a, "step (a), Signorini");
  if (!a.converged) return a;

  // (b): persistency on the nodes in contact after (a), none on the others.
  ContactSetting b{first.law, first.weight};
  bool any = false;
  for (int p = 0; p < b.size(); ++p) {
    ContactLaw& law = b.law[p];
    if (a.normal_status[p] == NormalStatus::free) {
      law = ContactLaw{}; // no wall, no friction: a compliance of stiffness 0
      law.normal = NormalLaw::compliance;
      continue;
    }
    any = true;
    law.normal = NormalLaw::signorini;
    law.depth = start.penetration[p];
    if (p_.persistency == Persistency::midpoint)
      law.depth += 0.5 * start.time_step * start.normal_velocity[p];
  }
  if (!any) return a;
  ContactStepSolution s = a; // phase() adds its iterations to the first phase's
  phase(bulk, b, iterate, s, "step (b), persistency");
  return s;
}

} // namespace sig
