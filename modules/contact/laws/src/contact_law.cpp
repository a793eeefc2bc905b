#include "contact/contact_law.hpp"

#include <Eigen/Geometry>

#include "core/error.hpp"

#include <cmath>
#include <sstream>

namespace sig {

ContactFrame contact_frame(const Eigen::Ref<const Eigen::VectorXd>& n) {
  const auto d = n.size();
  SIG_VERIFY(d == 2 || d == 3, "contact frame: a normal of " << d << " components");
  ContactFrame R(d, d);
  if (d == 2) {
    R.col(0) = contact_tangent(n);
  } else {
    Eigen::Index axis = 0;
    n.cwiseAbs().minCoeff(&axis);
    const Eigen::Vector3d normal = n;
    Eigen::Vector3d t1 = Eigen::Vector3d::Unit(axis) - normal[axis] * normal;
    t1.normalize();
    R.col(0) = t1;
    R.col(1) = normal.cross(t1);
  }
  R.col(d - 1) = -n;
  return R;
}

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
  case NormalLaw::compliance_bilateral:
    return "compliance-bilateral";
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
  case FrictionLaw::nonmonotone:
    return "nonmonotone";
  case FrictionLaw::mu1:
    return "mu1";
  case FrictionLaw::mu2:
    return "mu2";
  }
  return "?";
}

std::string to_string(FrictionBound bound) {
  return bound == FrictionBound::normal ? "normal" : "compliance";
}

std::string to_string(SlipMeasure measure) {
  return measure == SlipMeasure::slip ? "slip" : "slip-rate";
}

NormalLaw normal_law_named(const std::string& name) {
  for (NormalLaw law :
       {NormalLaw::signorini, NormalLaw::compliance, NormalLaw::compliance_unilateral,
        NormalLaw::damped, NormalLaw::damped_unilateral, NormalLaw::compliance_bilateral})
    if (to_string(law) == name) return law;
  SIG_VERIFY(false, "normal law '" << name << "' is unknown; known: " << normal_law_names);
  return NormalLaw::signorini;
}

FrictionLaw friction_law_named(const std::string& name) {
  for (FrictionLaw law : {FrictionLaw::none, FrictionLaw::tresca, FrictionLaw::coulomb,
                          FrictionLaw::nonmonotone, FrictionLaw::mu1, FrictionLaw::mu2})
    if (to_string(law) == name) return law;
  SIG_VERIFY(false, "friction law '" << name << "' is unknown; known: " << friction_law_names);
  return FrictionLaw::none;
}

FrictionBound friction_bound_named(const std::string& name) {
  for (FrictionBound bound : {FrictionBound::normal, FrictionBound::compliance})
    if (to_string(bound) == name) return bound;
  SIG_VERIFY(false, "friction bound '" << name << "' is unknown; known: normal, compliance");
  return FrictionBound::normal;
}

SlipMeasure slip_measure_named(const std::string& name) {
  for (SlipMeasure measure : {SlipMeasure::slip, SlipMeasure::slip_rate})
    if (to_string(measure) == name) return measure;
  SIG_VERIFY(false, "slip measure '" << name << "' is unknown; known: slip, slip-rate");
  return SlipMeasure::slip;
}

NormalLaw normal_law_of_id(long id) {
  SIG_VERIFY(id >= 1 && id <= 6, "normal law id "
                                     << id
                                     << " is unknown; known: 1 = signorini, 2 = compliance, 3 = "
                                        "compliance-unilateral, 4 = damped, 5 = "
                                        "damped-unilateral, 6 = compliance-bilateral");
  return static_cast<NormalLaw>(id);
}

FrictionLaw friction_law_of_id(long id) {
  SIG_VERIFY(id >= 0 && id <= 5, "friction law id "
                                     << id
                                     << " is unknown; known: 0 = none, 1 = tresca, 2 = coulomb, "
                                        "3 = nonmonotone, 4 = mu1, 5 = mu2");
  return static_cast<FrictionLaw>(id);
}

FrictionBound friction_bound_of_id(long id) {
  SIG_VERIFY(id == 0 || id == 1,
             "friction bound id " << id << " is unknown; known: 0 = normal, 1 = compliance");
  return static_cast<FrictionBound>(id);
}

SlipMeasure slip_measure_of_id(long id) {
  SIG_VERIFY(id == 0 || id == 1,
             "slip measure id " << id << " is unknown; known: 0 = slip, 1 = slip-rate");
  return static_cast<SlipMeasure>(id);
}

double friction_coefficient(const ContactLaw& law, double r) {
  switch (law.friction) {
  case FrictionLaw::coulomb:
    return law.mu;
  case FrictionLaw::nonmonotone:
    return (law.a - law.b) * std::exp(-law.alpha * r) + law.b;
  default:
    return 0.0;
  }
}

double d_friction_coefficient(const ContactLaw& law, double r) {
  if (law.friction != FrictionLaw::nonmonotone) return 0.0;
  return -law.alpha * (law.a - law.b) * std::exp(-law.alpha * r);
}

double penetration_friction(const ContactLaw& law, double q_n) {
  if (!law.penetration_dependent()) return law.mu;
  if (q_n <= 0) return 0.0;
  if (q_n >= law.depth) return law.mu;
  const double crushed = q_n / law.depth; // of the asperities
  return law.friction == FrictionLaw::mu1 ? crushed * law.mu : (2.0 - crushed) * law.mu;
}

double d_penetration_friction(const ContactLaw& law, double q_n) {
  if (!law.penetration_dependent() || q_n <= 0 || q_n >= law.depth) return 0.0;
  return (law.friction == FrictionLaw::mu1 ? 1.0 : -1.0) * law.mu / law.depth;
}

PressedFriction penetration_friction_pressed(const ContactLaw& law, double q_n) {
  if (q_n != 0 || !law.penetration_dependent())
    return {penetration_friction(law, q_n), d_penetration_friction(law, q_n)};
  const double slope = law.mu / law.depth;
  return law.friction == FrictionLaw::mu1 ? PressedFriction{0.0, slope}
                                          : PressedFriction{2.0 * law.mu, -slope};
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
  if (law.normal == NormalLaw::compliance_bilateral && std::isfinite(law.c3))
    return problem("c3", normal, " has no truncation, got c3 = ", law.c3);
  if (law.normal == NormalLaw::compliance_bilateral && law.has_friction())
    return problem("law", normal,
                   " is frictionless (its springs pull too, so no friction bound "
                   "is defined where they do): give FRICTION law=none");
  if (law.held_normal && law.friction != FrictionLaw::none)
    return problem("law",
                   "a node whose normal component a Dirichlet condition holds is out of "
                   "contact and has no friction, got ",
                   to_string(law.friction));
  if (!(std::isfinite(law.depth) && (law.depth >= 0 || law.held_normal)))
    return problem("g", "must be >= 0 (the depth of the wall), got ", law.depth);
  if (!(std::isfinite(law.threshold) && law.threshold >= 0))
    return problem("threshold", "must be >= 0 (a traction), got ", law.threshold);
  // The parameters of (1.39), 0 when unused: a >= b >= 0, alpha >= 0 (alpha = 0 or a = b is
  // Coulomb with mu = a).
  if (!(std::isfinite(law.a) && law.a >= 0)) return problem("a", "must be >= 0, got ", law.a);
  if (!(std::isfinite(law.b) && law.b >= 0)) return problem("b", "must be >= 0, got ", law.b);
  if (law.b > law.a)
    return problem("b", "must be <= a (1.39): mu(r) falls from a at r = 0 to b, got b = ", law.b,
                   " > a = ", law.a);
  if (!(std::isfinite(law.alpha) && law.alpha >= 0))
    return problem("alpha", "must be >= 0 (the decay of mu per unit slip), got ", law.alpha);
  // An unused mu or threshold is 0: the ranges hold whatever the friction law (nonmonotone's
  // frozen mu after a, b, alpha, so that the card's a, from which it starts, is named).
  if (!(std::isfinite(law.mu) && law.mu >= 0)) return problem("mu", "must be >= 0, got ", law.mu);
  // (8.3) measures the penetration against the asperities' depth g.
  if (law.penetration_dependent() && !(law.depth > 0))
    return problem("g", "must be > 0 for friction law=", to_string(law.friction),
                   ": mu rises or falls over the penetration 0 < q_n < g (8.3), got ", law.depth);
  // Bounding by the compliance pressure needs one: signorini's bound would vanish everywhere.
  if (law.has_coefficient() && law.bound == FrictionBound::compliance && !law.has_compliance())
    return problem("bound", "compliance bounds the slip by mu p(q_n), and ", normal,
                   " has no compliance pressure p: the bound would be 0 (use bound=normal or "
                   "law=none)");
  return std::nullopt;
}

std::string describe(const ContactLaw& law) {
  std::ostringstream out;
  if (law.held_normal) out << "normal held at q_n=" << law.depth << ", ";
  for (int k = 0; k < 2; ++k)
    if (law.held_tangent[k]) out << "slip " << k + 1 << " held at " << law.held_slip[k] << ", ";
  out << to_string(law.normal);
  if (law.has_compliance()) {
    out << " cn=" << law.cn;
    if (std::isfinite(law.c3)) out << " c3=" << law.c3;
  }
  if (law.has_wall()) out << " g=" << law.depth;
  out << ", friction " << to_string(law.friction);
  if (law.friction == FrictionLaw::coulomb || law.penetration_dependent()) out << " mu=" << law.mu;
  if (law.friction == FrictionLaw::nonmonotone)
    out << " a=" << law.a << " b=" << law.b << " alpha=" << law.alpha << " of " << to_string(law.of)
        << " (mu=" << law.mu << ")";
  if (law.has_coefficient()) out << " bound=" << to_string(law.bound);
  if (law.friction == FrictionLaw::tresca) out << " threshold=" << law.threshold;
  return out.str();
}

} // namespace sig
