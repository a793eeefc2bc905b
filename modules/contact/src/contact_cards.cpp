#include "contact/contact_elements.hpp"

#include "core/datafile.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sig {

namespace {

// A point or vector of the mesh's dimension d: x,y in 2D, x,y,z in 3D.
Point vector_field(const Card& card, const std::string& name, int d) {
  const std::vector<double> v = card.reals(name);
  if (static_cast<int>(v.size()) != d ||
      !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) {
    std::ostringstream what;
    what << "expects " << (d == 3 ? "three finite numbers x,y,z" : "two finite numbers x,y")
         << " (the mesh is " << d << "D); got " << v.size() << " value(s)";
    card.fail(name, what.str());
  }
  return Eigen::Map<const Eigen::VectorXd>(v.data(), d);
}

// The reference must carry Gamma3 facets: list what the mesh has so the user can pick.
void check_reference(const Card& card, const Mesh& mesh, int ref) {
  std::set<int> present;
  for (const Facet& e : mesh.facets)
    present.insert(e.ref);
  if (present.count(ref)) return;
  std::ostringstream what;
  what << "reference " << ref << " carries no " << mesh.facet_name()
       << " of the mesh; references on " << mesh.facet_name() << "s:";
  if (present.empty()) what << " none";
  for (int r : present)
    what << ' ' << r;
  card.fail("ref", what.str());
}

std::unique_ptr<Obstacle> obstacle_from_card(const Card& card, int d) {
  const std::string kind = card.choice("obstacle", {"plane", "disc", "sphere", "cylinder"});
  const std::string round = d == 3 ? "sphere" : "disc";
  if (kind == "cylinder" && d != 3)
    card.fail("obstacle", "obstacle=cylinder is 3D, the mesh is 2D: its section is obstacle=disc");
  if (kind != "plane" && kind != round && kind != "cylinder")
    card.fail("obstacle", "obstacle=" + kind + " is " + (d == 3 ? "2D" : "3D") + ", the mesh is " +
                              std::to_string(d) + "D: use obstacle=" + round);
  // The fields of another obstacle would be ignored: the deck says something it does not get.
  // In this order, so that a field of two obstacles is named as the simpler one's.
  const std::vector<std::pair<std::string, std::vector<std::string>>> fields = {
      {"plane", {"point", "normal"}},
      {round, {"centre", "radius"}},
      {"cylinder", {"centre", "axis", "radius"}}};
  for (const auto& [other, names] : fields)
    for (const std::string& field : names)
      if (card.has(field) && std::ranges::none_of(fields, [&](const auto& owner) {
            return owner.first == kind && std::ranges::count(owner.second, field) > 0;
          }))
        card.fail(field, "is a field of obstacle=" + other + ", not of obstacle=" + kind +
                             " (remove it, or change the obstacle)");
  if (kind == round) {
    const Point centre = vector_field(card, "centre", d);
    const double radius = card.real("radius"); // > 0: core/ranges.hpp
    return std::make_unique<Disc>(centre, radius);
  }
  if (kind == "cylinder") {
    const Point centre = vector_field(card, "centre", d);
    const Point axis = vector_field(card, "axis", d);
    if (axis.norm() == 0)
      card.fail("axis", "zero-length axis; give its direction, e.g. axis=1,0,0");
    return std::make_unique<Cylinder>(centre, axis, card.real("radius"));
  }
  const Point point = vector_field(card, "point", d);
  const Point normal = vector_field(card, "normal", d);
  if (normal.norm() == 0)
    card.fail("normal", std::string("zero-length normal; give the outward normal of the obstacle, "
                                    "pointing to the body's side (e.g. normal=") +
                            (d == 3 ? "0,0,1 for the foundation x3 <= 0)"
                                    : "0,1 for the foundation x2 <= 0)"));
  return std::make_unique<HalfPlane>(point, normal);
}

/// A field the law does not read is a mistake in the deck (a compliance given to signorini
/// would be silently ignored otherwise).
void refuse_unused(const Card& card, const std::string& field, const std::string& law) {
  if (card.has(field)) card.fail(field, "is not a parameter of law=" + law);
}

/// The normal law and its parameters from CONTACT.
ContactLaw normal_law_from_card(const Card& card) {
  ContactLaw law;
  const std::string name = card.choice("law", normal_law_choices);
  law.normal = normal_law_named(name);
  if (law.has_compliance())
    law.cn = card.real("cn");
  else
    refuse_unused(card, "cn", name);
  // The truncation is chapter 6's, of a compliance in the penetration.
  if (law.has_compliance() && !law.in_velocity() && law.normal != NormalLaw::compliance_bilateral)
    law.c3 = card.real("c3", law.c3);
  else
    refuse_unused(card, "c3", name);
  if (law.normal == NormalLaw::compliance_unilateral && !card.has("g") && !card.has("gap"))
    card.fail("g", "law=compliance-unilateral needs the depth of its compliant layer, the wall "
                   "at q_n = g");
  if (law.normal == NormalLaw::damped_unilateral && !card.has("g") && !card.has("gap"))
    card.fail("g", "law=damped-unilateral needs its velocity bound, v_n <= g");
  if (law.has_wall()) {
    law.depth = wall_depth(card);
  } else {
    refuse_unused(card, "g", name);
    refuse_unused(card, "gap", name);
  }
  return law;
}

/// The friction law of the FRICTION card (if any) on reference `ref`, into `law`.
void friction_from_cards(const Datafile& datafile, int ref, ContactLaw& law) {
  for (const Card* card : datafile.all("FRICTION")) {
    const long friction_ref = card->integer("ref");
    if (friction_ref != ref)
      card->fail("ref", "reference " + std::to_string(friction_ref) +
                            " has no CONTACT card (the CONTACT card is on ref=" +
                            std::to_string(ref) + ")");
    const std::string name = card->choice("law", friction_law_choices);
    law.friction = friction_law_named(name);
    if (law.friction == FrictionLaw::coulomb || law.penetration_dependent())
      law.mu = card->real("mu");
    else
      refuse_unused(*card, "mu", name);
    if (law.penetration_dependent() && !(law.depth > 0))
      card->fail("law", "law=" + name + " needs the asperities' depth g > 0 on the CONTACT card: " +
                            "mu varies over the penetration 0 < q_n < g (8.3)");
    if (law.friction == FrictionLaw::tresca)
      law.threshold = card->real("threshold");
    else
      refuse_unused(*card, "threshold", name);
    if (law.has_coefficient())
      law.bound = friction_bound_named(card->choice("bound", friction_bound_choices, "normal"));
    else
      refuse_unused(*card, "bound", name);
    if (law.friction == FrictionLaw::nonmonotone) {
      law.a = card->real("a");
      law.b = card->real("b");
      law.alpha = card->real("alpha");
      law.of = slip_measure_named(card->choice("of", slip_measure_choices, "slip"));
      law.mu = law.a; // mu(0): the first convex solve starts from no slip (ALGORITHMS.md 1.3)
    } else {
      for (const char* field : {"a", "b", "alpha", "of"})
        refuse_unused(*card, field, name);
    }
    if (const std::optional<LawProblem> problem = law_problem(law))
      card->fail(problem->field, problem->what);
  }
}

} // namespace

const Card* friction_card_with_law(const Datafile& datafile) {
  for (const Card* card : datafile.all("FRICTION"))
    if (card->choice("law", friction_law_choices) != "none") return card;
  return nullptr;
}

double wall_depth(const Card& contact) {
  if (contact.has("g") && contact.has("gap"))
    contact.fail("gap", "give the wall depth once: g= (gap= is its old spelling)");
  return contact.has("gap") ? contact.real("gap") : contact.real("g");
}

std::optional<ContactElements> contact_from_cards(const Datafile& datafile, const Mesh& mesh) {
  const std::vector<const Card*> cards = datafile.all("CONTACT");
  const std::vector<const Card*> friction = datafile.all("FRICTION");
  if (cards.empty() && !friction.empty())
    friction.front()->fail("ref", "friction needs a CONTACT card on the same reference");
  if (cards.empty()) return std::nullopt;
  if (friction.size() > 1)
    friction[1]->fail("", "only one FRICTION card is supported (one contact boundary)");
  if (cards.size() > 1)
    cards[1]->fail("", "only one CONTACT card is supported (one contact boundary, one obstacle)");
  const Card& card = *cards.front();

  const long ref = card.integer("ref");
  check_reference(card, mesh, static_cast<int>(ref));
  ContactLaw law = normal_law_from_card(card);
  if (const std::optional<LawProblem> problem = law_problem(law))
    card.fail(problem->field == "g" && card.has("gap") ? "gap" : problem->field, problem->what);
  friction_from_cards(datafile, static_cast<int>(ref), law);
  const std::unique_ptr<Obstacle> obstacle = obstacle_from_card(card, mesh.dim);
  std::vector<int> excluded;
  std::vector<int> zone = mesh.nodes_with_ref(static_cast<int>(ref));
  std::sort(zone.begin(), zone.end());
  if (card.has("exclude"))
    for (long other : card.integers("exclude")) {
      const std::vector<int> nodes = mesh.nodes_with_ref(static_cast<int>(other));
      if (nodes.empty())
        card.fail("exclude", "reference " + std::to_string(other) + " carries no mesh node");
      // A reference that shares no node with the contact zone would exclude nothing, silently.
      if (std::none_of(nodes.begin(), nodes.end(), [&zone](int node) {
            return std::binary_search(zone.begin(), zone.end(), node);
          }))
        card.fail("exclude", "reference " + std::to_string(other) +
                                 " shares no node with the contact boundary (ref=" +
                                 std::to_string(ref) + "): it would exclude nothing");
      excluded.insert(excluded.end(), nodes.begin(), nodes.end());
    }

  // A node starting inside the obstacle is a geometric error of this card's obstacle.
  try {
    return build_contact_elements(mesh, static_cast<int>(ref), *obstacle, law, 1.0, excluded);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    card.fail("obstacle", e.what());
  }
}

} // namespace sig
