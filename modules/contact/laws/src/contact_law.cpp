#include "contact/contact_law.hpp"

#include "core/error.hpp"

#include <cmath>
#include <sstream>

namespace sig {

std::string to_string(NormalLaw law) {
  switch (law) {
  case NormalLaw::signorini:
    return "signorini";
  case NormalLaw::compliance:
    return "compliance";
  case NormalLaw::compliance_unilateral:
    return "compliance-unilateral";
  case NormalLaw::damped:
    return "damped";
  case NormalLaw::damped_unilateral:
    return "damped-unilateral";
  }
  return "?";
}

std::string to_string(FrictionLaw law) {
  switch (law) {
  case FrictionLaw::none:
    return "none";
  case FrictionLaw::tresca:
    return "tresca";
  case FrictionLaw::coulomb:
    return "coulomb";
  }
  return "?";
}

NormalLaw normal_law_named(const std::string& name) {
  for (NormalLaw law :
       {NormalLaw::signorini, NormalLaw::compliance, NormalLaw::compliance_unilateral,
        NormalLaw::damped, NormalLaw::damped_unilateral})
    if (to_string(law) == name) return law;
  SIG_VERIFY(false, "normal law '" << name << "' is unknown; known: " << normal_law_names);
  return NormalLaw::signorini;
}

FrictionLaw friction_law_named(const std::string& name) {
  for (FrictionLaw law : {FrictionLaw::none, FrictionLaw::tresca, FrictionLaw::coulomb})
    if (to_string(law) == name) return law;
  SIG_VERIFY(false, "friction law '" << name << "' is unknown; known: " << friction_law_names);
  return FrictionLaw::none;
}

NormalLaw normal_law_of_id(long id) {
  SIG_VERIFY(id >= 1 && id <= 5, "normal law id " << id
                                                  << " is unknown; known: 1 = signorini, "
                                                     "2 = compliance, 3 = "
                                                     "compliance-unilateral, 4 = damped, 5 = "
                                                     "damped-unilateral");
  return static_cast<NormalLaw>(id);
}

FrictionLaw friction_law_of_id(long id) {
  SIG_VERIFY(id >= 0 && id <= 2,
             "friction law id " << id << " is unknown; known: 0 = none, 1 = tresca, 2 = coulomb");
  return static_cast<FrictionLaw>(id);
}

std::optional<LawProblem> law_problem(const ContactLaw& law) {
  const auto problem = [](const char* field, const auto&... what) {
    std::ostringstream out;
    (out << ... << what);
    return std::optional<LawProblem>(LawProblem{field, out.str()});
  };
  const std::string normal = "law=" + to_string(law.normal);
  if (law.has_compliance() && !(std::isfinite(law.cn) && law.cn > 0))
    return problem("cn", "must be > 0 for ", normal, ", got ", law.cn);
  // An unused cn is 0 and an unused c3 infinite: the ranges hold whatever the normal law, so a
  // CONT file cannot carry a value the cards would refuse.
  if (!(std::isfinite(law.cn) && law.cn >= 0)) return problem("cn", "must be >= 0, got ", law.cn);
  if (!(law.c3 > 0)) return problem("c3", "must be > 0 (a truncation pressure), got ", law.c3);
  if (!(std::isfinite(law.depth) && law.depth >= 0))
    return problem("g", "must be >= 0 (the depth of the wall), got ", law.depth);
  // An unused mu or threshold is 0: the ranges hold whatever the friction law.
  if (!(std::isfinite(law.mu) && law.mu >= 0)) return problem("mu", "must be >= 0, got ", law.mu);
  if (!(std::isfinite(law.threshold) && law.threshold >= 0))
    return problem("threshold", "must be >= 0 (a traction), got ", law.threshold);
  return std::nullopt;
}

std::string describe(const ContactLaw& law) {
  std::ostringstream out;
  out << to_string(law.normal);
  if (law.has_compliance()) {
    out << " cn=" << law.cn;
    if (std::isfinite(law.c3)) out << " c3=" << law.c3;
  }
  if (law.has_wall()) out << " g=" << law.depth;
  out << ", friction " << to_string(law.friction);
  if (law.friction == FrictionLaw::coulomb) out << " mu=" << law.mu;
  if (law.friction == FrictionLaw::tresca) out << " threshold=" << law.threshold;
  return out.str();
}

} // namespace sig
