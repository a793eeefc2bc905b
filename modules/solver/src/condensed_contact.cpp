#include "solver/condensed_contact.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace sig {

CondensedSolution solve_condensed_contact(CondensedProblem problem, const ContactSetting& setting,
                                          const ContactSolverParameters& parameters,
                                          const Eigen::VectorXd& start,
                                          const CondensedConvexification& loop) {
  const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
  const int m = setting.size();
  Eigen::VectorXd default_stiffness(m);
  for (int p = 0; p < m; ++p)
    default_stiffness[p] = off_wall_stiffness(*method, setting.law[p], setting.weight[p]);
  const bool friction = !problem.tangential_dof.empty();
  CondensedBulk bulk(std::move(problem), default_stiffness, start);
  ContactIterate iterate;
  CondensedSolution s;
  const ContactNewtonOptions inner = newton_options(parameters);
  if (needs_convexification(setting.law)) {
    const bool rate = std::any_of(setting.law.begin(), setting.law.end(), [](const ContactLaw& l) {
      return l.friction == FrictionLaw::nonmonotone && l.of == SlipMeasure::slip_rate;
    });
    SIG_VERIFY(!rate || loop.slip, "a nonmonotone law of the slip rate (of=slip-rate) needs the "
                                   "caller's slip-rate measure; the slip from the reference "
                                   "is not a rate");
    ConvexificationMeasures measures;
    measures.displacement = [&](const ContactBulk&) {
      return loop.displacement ? loop.displacement(bulk.displacement()) : bulk.displacement();
    };
    measures.norm = loop.norm;
    if (loop.slip)
      measures.slip = [&](const ContactBulk&) { return loop.slip(bulk.displacement()); };
    s.convexification = convexify(bulk, setting, *method, inner, loop.options, measures, iterate);
    s.contact = s.convexification->last;
  } else {
    s.contact = solve_contact(bulk, setting, *method, inner, iterate);
  }
  s.w = bulk.displacement();
  // A method's tangential multiplier has d - 1 components per node (two in 3D).
  int per_node = method->multiplier_unknowns(friction);
  if (friction && per_node > 1) per_node += bulk.tangents() - 1;
  s.multiplier_unknowns = m * per_node;
  return s;
}

} // namespace sig
