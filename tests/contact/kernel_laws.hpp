#pragma once
// The laws the kernel tests run through, in 2D and in 3D (test_contact_kernel.cpp,
// test_contact_kernel_3d.cpp): every normal law with every friction law and bound.
#include "contact/contact_law.hpp"

#include <vector>

namespace sig {

inline ContactLaw law_of(NormalLaw normal, FrictionLaw friction,
                         FrictionBound bound = FrictionBound::normal) {
  ContactLaw law;
  law.normal = normal;
  law.cn = 7.5;
  law.depth = law.has_wall() ? 0.4 : 0.0;
  law.friction = friction;
  if (law.penetration_dependent()) law.depth = 0.4; // the asperities' depth, walls or not
  law.mu = 0.3;
  law.threshold = 2.0;
  if (friction == FrictionLaw::nonmonotone) { // mu frozen at mu(r) of some slip r = 0.2
    law.a = 0.5;
    law.b = 0.1;
    law.alpha = 3.0;
    law.mu = friction_coefficient(law, 0.2);
  }
  if (law.has_coefficient()) law.bound = bound;
  return law;
}

struct KernelCase {
  NormalLaw normal;
  FrictionLaw friction;
  FrictionBound bound = FrictionBound::normal;
};

/// mu1 / mu2: the penetrations a and b lie on one piece of the coefficient (its kinks at q_n = 0
/// and g), where a central difference of the kernel does not straddle one.
inline bool same_coefficient_piece(const ContactLaw& law, double a, double b) {
  return d_penetration_friction(law, a) == d_penetration_friction(law, b) &&
         (penetration_friction(law, a) > 0) == (penetration_friction(law, b) > 0);
}

/// Every normal law with every friction law and bound the code has.
inline std::vector<KernelCase> every_kernel_case() {
  return {
      KernelCase{NormalLaw::signorini, FrictionLaw::none},
      KernelCase{NormalLaw::signorini, FrictionLaw::tresca},
      KernelCase{NormalLaw::signorini, FrictionLaw::coulomb},
      KernelCase{NormalLaw::compliance, FrictionLaw::none},
      KernelCase{NormalLaw::compliance, FrictionLaw::tresca},
      KernelCase{NormalLaw::compliance, FrictionLaw::coulomb},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::none},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::tresca},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::coulomb},
      KernelCase{NormalLaw::signorini, FrictionLaw::nonmonotone},
      KernelCase{NormalLaw::compliance, FrictionLaw::nonmonotone},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::nonmonotone},
      // The bound of (4.6)/(5.6): the compliance pressure only.
      KernelCase{NormalLaw::compliance, FrictionLaw::coulomb, FrictionBound::compliance},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::coulomb, FrictionBound::compliance},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::nonmonotone,
                 FrictionBound::compliance},
      KernelCase{NormalLaw::signorini, FrictionLaw::mu1},
      KernelCase{NormalLaw::compliance, FrictionLaw::mu1},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::mu1},
      KernelCase{NormalLaw::compliance, FrictionLaw::mu2},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::mu2},
      KernelCase{NormalLaw::compliance_unilateral, FrictionLaw::mu2, FrictionBound::compliance},
      KernelCase{NormalLaw::damped, FrictionLaw::coulomb},
      KernelCase{NormalLaw::damped_unilateral, FrictionLaw::none},
      KernelCase{NormalLaw::damped_unilateral, FrictionLaw::coulomb},
      KernelCase{NormalLaw::compliance_bilateral, FrictionLaw::none}};
}

} // namespace sig
