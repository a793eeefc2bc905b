#pragma once
// The laws of one contact element (thesis ch. 1, l.1284-1960): a normal law and a friction law
// with their parameters. Forces are pressures here (a traction on Gamma3, the thesis's
// multiplier densities); the nodal weight turns them into nodal forces.
//
// Kinematics of a contact node (contact_elements.hpp): q_n = u_n - d is the penetration beyond
// the obstacle surface (u_n the normal displacement towards the obstacle, d the initial gap, so
// q_n > 0 means the node is past the surface), q_t the tangential displacement (slip) along the
// tangent t = (n2, -n1). One depth g describes every rigid wall of the code: the wall sits at
// q_n = g, g beyond the obstacle surface.
//   signorini               (1.22) the wall: q_n <= g, N >= 0, N (q_n - g) = 0 (g = 0: the
//                           surface itself; g > 0: the body may sink g into the obstacle freely)
//   compliance              (1.24) N = p(q_n) = cn [q_n]+, truncated min(cn [q_n]+, c3) (ch. 6);
//                           no wall
//   compliance-unilateral   (1.26) N = p(q_n) while q_n < g, a Signorini wall at q_n = g (g the
//                           depth of the compliant layer)
//   compliance-bilateral    N = cn q_n on both sides of the surface: springs that also pull (a
//                           foundation glued to the body), no truncation, frictionless. A test
//                           law: the Winkler strip of ALGORITHMS.md 3.6 has a semi-analytic
//                           solution with it
// and the laws in velocity of chapter 5 (quasistatic march in velocity, sig-march
// scheme=quasistatic): the same kernels with q_n the normal velocity v_n towards the obstacle and
// q_t the tangential velocity (the slip rate), so that g is a velocity bound:
//   damped                  (1.25) N = p(v_n) = cn [v_n]+, the damped (instantaneous) response
//   damped-unilateral       (1.28) N = p(v_n) while v_n < g, the unilateral bound v_n <= g
//                           beyond (the thesis's statuses RNI and CUV are CN and CU here)
// and the friction laws, with s the slip bound (|T| <= s, T = s sign(q_t) where q_t != 0):
//   none                    T = 0
//   tresca                  (1.33) s = threshold, a given traction, on every contact element
//                           whatever its normal state (the classical Tresca model)
//   coulomb                 (1.35) s = mu N, N the whole normal pressure (compliance + wall)
//   nonmonotone             (1.39) s = mu(r) N with mu(r) = (a - b) exp(-alpha r) + b, a >= b,
//                           r the magnitude of the slip (of=slip, ch. 4) or of the slip rate
//                           (of=slip-rate, ch. 6). Non-convex: one convex solve is Coulomb with
//                           the coefficient `mu` frozen per node, which the convexification loop
//                           (solver module) sets from the previous iterate's slip
//   mu1, mu2                (8.3) s = mu(q_n) N, the coefficient a function of the penetration q_n
//                           through the asperities of depth g (the wall depth: g > 0), with
//                           mu0 = `mu`: mu1 rises from 0 to mu0 over 0 < q_n < g (mu0 q_n / g),
//                           mu2 falls from 2 mu0 to mu0 ((2 - q_n / g) mu0); both are 0 for
//                           q_n <= 0 and mu0 for q_n >= g, where the asperities are crushed
// The source of a Coulomb-type bound (coulomb, nonmonotone, mu1, mu2), `bound`:
//   normal                  s = mu N, N the whole normal pressure: classical Coulomb (1.35)
//   compliance              s = mu p(min(q_n, g)), the compliance (or damper) pressure only, as
//                           (4.6) and (5.6): the wall's reaction never enters the bound, so on the
//                           wall it is Tresca's mu p(g) (l.5767)
// A time step of sig-march may replace a displacement compliance by its secant over the step
// (`secant`, the specific penalty of [62], (3.51), (8.32)): N = cn p_spe(previous, q_n), with
// p_spe of complementarity.hpp and `previous` the penetration at the start of the step, whose
// work over the step is exactly the change of the compliance's potential cn [q_n]_+^2 / 2. The
// strategies of the march set it per step; it is never stored in CONT. Under a secant law mu1 and
// mu2 take the deepest penetration of the step, max(previous, q_n): the asperities crushed so far
// in the step ([choice]: with mu(q_n) the bound mu2(q_n) N jumps from 0 to 2 mu0 N at q_n = 0, N
// being the secant's force of a node that leaves the obstacle, not 0 as in (8.2), and the
// semi-smooth Newton method cycles on that jump, seen on scene 8b's ring; with the step's
// deepest penetration the bound is continuous, since N -> 0 as that penetration -> 0).
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace sig {

/// The tangent of the contact frame at a node of obstacle normal n (pointing to the body's
/// side): t = (n2, -n1), +x1 on the foundation x2 <= 0.
inline Eigen::Vector2d contact_tangent(const Eigen::Vector2d& n) {
  return {n.y(), -n.x()};
}

/// The contact frame of a node, d x d (d = 2, 3): its columns are the tangents and -n, so that
/// u = R w takes w = (slips, normal displacement towards the obstacle). 2D: (t, -n) with t =
/// contact_tangent(n). 3D: (t1, t2, -n) with t1 the coordinate axis least aligned with n (the
/// first of equals) made orthogonal to n, and t2 = n x t1: on the foundation x3 >= 0 (n = e3),
/// t1 = e1 and t2 = e2, and det R = -1 in both dimensions. The axis is chosen from n alone, so
/// equal normals get equal frames.
using ContactFrame = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 3, 3>;
ContactFrame contact_frame(const Eigen::Ref<const Eigen::VectorXd>& n);

enum class NormalLaw {
  signorini = 1,
  compliance = 2,
  compliance_unilateral = 3,
  damped = 4,
  damped_unilateral = 5,
  compliance_bilateral = 6
};
enum class FrictionLaw { none = 0, tresca = 1, coulomb = 2, nonmonotone = 3, mu1 = 4, mu2 = 5 };
enum class FrictionBound { normal = 0, compliance = 1 };
enum class SlipMeasure { slip = 0, slip_rate = 1 };

inline constexpr const char* normal_law_names =
    "signorini | compliance | compliance-unilateral | damped | damped-unilateral | "
    "compliance-bilateral";
inline constexpr const char* friction_law_names =
    "none | tresca | coulomb | nonmonotone | mu1 | mu2";
/// The same names as a card field's choices (Card::choice).
inline constexpr std::initializer_list<const char*> normal_law_choices = {
    "signorini", "compliance",        "compliance-unilateral",
    "damped",    "damped-unilateral", "compliance-bilateral"};
inline constexpr std::initializer_list<const char*> friction_law_choices = {
    "none", "tresca", "coulomb", "nonmonotone", "mu1", "mu2"};
inline constexpr std::initializer_list<const char*> friction_bound_choices = {"normal",
                                                                              "compliance"};
inline constexpr std::initializer_list<const char*> slip_measure_choices = {"slip", "slip-rate"};

std::string to_string(NormalLaw law);
std::string to_string(FrictionLaw law);
std::string to_string(FrictionBound bound);
std::string to_string(SlipMeasure measure);
/// The laws of their card names; sig::Error listing the names for anything else.
NormalLaw normal_law_named(const std::string& name);
FrictionLaw friction_law_named(const std::string& name);
FrictionBound friction_bound_named(const std::string& name);
SlipMeasure slip_measure_named(const std::string& name);
/// The laws of their CONT ids (the enum values); sig::Error for an unknown id.
NormalLaw normal_law_of_id(long id);
FrictionLaw friction_law_of_id(long id);
FrictionBound friction_bound_of_id(long id);
SlipMeasure slip_measure_of_id(long id);

struct ContactLaw {
  NormalLaw normal = NormalLaw::signorini;
  double cn = 0; ///< compliance slope, pressure per unit penetration (> 0 for compliance laws)
  double c3 = std::numeric_limits<double>::infinity(); ///< truncation pressure (ch. 6), > 0
  double depth = 0;    ///< g >= 0: the wall at q_n = g (signorini, compliance-unilateral)
  bool secant = false; ///< compliance, compliance-unilateral (c3 unused): the specific penalty
  double previous = 0; ///< secant: the penetration at the start of the time step
  FrictionLaw friction = FrictionLaw::none;
  /// coulomb: the friction coefficient >= 0; nonmonotone: the coefficient of the present convex
  /// solve, frozen per node (mu(0) = a until the convexification loop sets it); mu1, mu2: mu0
  double mu = 0;
  double threshold = 0;                        ///< tresca: slip bound, a traction >= 0
  FrictionBound bound = FrictionBound::normal; ///< coulomb, nonmonotone: what mu multiplies
  double a = 0;                                ///< nonmonotone: mu(0), >= b
  double b = 0;                                ///< nonmonotone: mu at large slip, >= 0
  double alpha = 0;                   ///< nonmonotone: decay per unit slip (or slip rate), >= 0
  SlipMeasure of = SlipMeasure::slip; ///< nonmonotone: what r measures
  /// Components of the node that a Dirichlet condition holds (a roller on a contact node), set by
  /// the solve stage from the deck's DIRICHLET cards, never stored in CONT. A held normal takes
  /// the node out of contact: a bilateral wall at q_n = depth whose reaction may pull, no
  /// compliance; a held tangential component sticks at its slip held_slip whatever its force
  /// (no bound: the condition's reaction, not friction). Component k is the tangent t_(k+1) of
  /// contact_frame: the one tangent in 2D (k = 0), either of the pair in 3D, where the other, if
  /// free, keeps the friction law on its line (|T_k| <= s: the cone cut by the held plane).
  bool held_normal = false;
  std::array<bool, 2> held_tangent{};
  std::array<double, 2> held_slip{};

  bool has_wall() const {
    return normal == NormalLaw::signorini || normal == NormalLaw::compliance_unilateral ||
           normal == NormalLaw::damped_unilateral || held_normal;
  }
  bool has_compliance() const { return normal != NormalLaw::signorini && !held_normal; }
  /// A law of the velocity (damped, damped-unilateral): q_n, q_t are velocities, g a velocity.
  bool in_velocity() const {
    return normal == NormalLaw::damped || normal == NormalLaw::damped_unilateral;
  }
  /// Some tangential component is held (held_tangent).
  bool held_tangential() const { return held_tangent[0] || held_tangent[1]; }
  bool has_friction() const { return friction != FrictionLaw::none || held_tangential(); }
  /// The bound is a coefficient times a pressure (coulomb, nonmonotone, mu1, mu2), not a given
  /// traction.
  bool has_coefficient() const {
    return friction == FrictionLaw::coulomb || friction == FrictionLaw::nonmonotone ||
           penetration_dependent();
  }
  /// The coefficient is a function of the penetration (mu1, mu2 of (8.3)).
  bool penetration_dependent() const {
    return friction == FrictionLaw::mu1 || friction == FrictionLaw::mu2;
  }
  bool operator==(const ContactLaw&) const = default;
};

/// The coefficient of friction at slip magnitude r >= 0: mu for coulomb, (1.39)
/// (a - b) exp(-alpha r) + b for nonmonotone, 0 for the other laws.
double friction_coefficient(const ContactLaw& law, double r);
/// d/dr of friction_coefficient: -alpha (a - b) exp(-alpha r) for nonmonotone, else 0.
double d_friction_coefficient(const ContactLaw& law, double r);

/// The coefficient of mu1 or mu2 (8.3) at penetration q_n, and its derivative in q_n (the kinks
/// at q_n = 0 and g belong to the flat sides: 0 at q_n <= 0, mu0 at q_n >= g); mu for coulomb and
/// nonmonotone (slope 0).
double penetration_friction(const ContactLaw& law, double q_n);
double d_penetration_friction(const ContactLaw& law, double q_n);
/// The coefficient and its slope that a press from q_n meets: those above, but at the kink
/// q_n = 0 the deeper side's (mu1: 0 rising by mu0 / g; mu2: 2 mu0 falling by mu0 / g), which the
/// apex rule of contact_kernel.hpp asks of a node at rest.
struct PressedFriction {
  double mu;
  double slope;
};
PressedFriction penetration_friction_pressed(const ContactLaw& law, double q_n);

/// Some law of `laws` has friction (the problem then has tangential unknowns).
inline bool any_friction(const std::vector<ContactLaw>& laws) {
  return std::any_of(laws.begin(), laws.end(),
                     [](const ContactLaw& l) { return l.has_friction(); });
}

/// A parameter out of its range: the card field that holds it (cn, c3, g, mu, threshold, a, b,
/// alpha, bound) and
/// why ("must be > 0 for law=compliance, got -1").
struct LawProblem {
  std::string field;
  std::string what;
};
/// The first inadmissible parameter of `law`, or nothing. The one statement of the parameter
/// ranges: the datafile reader (contact_cards.cpp) and the CONT reader (cont_io.cpp) both use
/// it, each naming its own file and place.
std::optional<LawProblem> law_problem(const ContactLaw& law);

/// "signorini g=0, coulomb mu=0.3" (logs and dumps).
std::string describe(const ContactLaw& law);

} // namespace sig
