#pragma once
// Scene 4's contact law for the unit tests: normal compliance cn with its wall at depth g, and the
// nonmonotone friction mu(r) = (a - b) exp(-alpha r) + b bounded by the compliance pressure (4.6),
// mu starting at a.
#include "contact/contact_law.hpp"

namespace sig::test {

inline ContactLaw compliance_nonmonotone(double cn, double g, double a, double b, double alpha) {
  ContactLaw law;
  law.normal = NormalLaw::compliance_unilateral;
  law.cn = cn;
  law.depth = g;
  law.friction = FrictionLaw::nonmonotone;
  law.bound = FrictionBound::compliance;
  law.a = a;
  law.b = b;
  law.alpha = alpha;
  law.mu = a;
  return law;
}

} // namespace sig::test
