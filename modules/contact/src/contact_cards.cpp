#include "contact/contact_elements.hpp"

#include "core/datafile.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>

namespace sig {

namespace {

Eigen::Vector2d pair_field(const Card& card, const std::string& name) {
  const std::vector<double> v = card.reals(name);
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1])) {
    std::ostringstream what;
    what << "expects two finite numbers x,y; got " << v.size() << " value(s)";
    card.fail(name, what.str());
  }
  return {v[0], v[1]};
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The reference must carry Gamma3 edges: list what the mesh has so the user can pick.
void check_reference(const Card& card, const Mesh& mesh, int ref) {
  std::set<int> present;
  for (const BoundaryEdge& e : mesh.edges)
    present.insert(e.ref);
  if (present.count(ref)) return;
  std::ostringstream what;
  what << "reference " << ref << " carries no edge of the mesh; references on edges:";
  if (present.empty()) what << " none";
  for (int r : present)
    what << ' ' << r;
  card.fail("ref", what.str());
}

std::unique_ptr<Obstacle> obstacle_from_card(const Card& card) {
  const std::string kind = card.choice("obstacle", {"plane", "disc"});
  if (kind == "disc") {
    const Eigen::Vector2d centre = pair_field(card, "centre");
    const double radius = card.real("radius");
    if (!(std::isfinite(radius) && radius > 0)) card.fail("radius", "must be > 0");
    return std::make_unique<Disc>(centre, radius);
  }
  const Eigen::Vector2d point = pair_field(card, "point");
  const Eigen::Vector2d normal = pair_field(card, "normal");
  if (normal.norm() == 0)
    card.fail("normal", "zero-length normal; give the outward normal of the obstacle, pointing "
                        "to the body's side (e.g. normal=0,1 for the foundation x2 <= 0)");
  return std::make_unique<HalfPlane>(point, normal);
}

} // namespace

std::optional<ContactElements> contact_from_cards(const Datafile& datafile, const Mesh& mesh) {
  const std::vector<const Card*> cards = datafile.all("CONTACT");
  if (cards.empty()) return std::nullopt;
  if (cards.size() > 1)
    cards[1]->fail("", "only one CONTACT card is supported (one contact boundary, one obstacle)");
  const Card& card = *cards.front();

  const long ref = card.integer("ref");
  check_reference(card, mesh, static_cast<int>(ref));
  const std::string law = lower(card.text("law", "signorini"));
  if (law != "signorini")
    card.fail("law", "law '" + law + "' is not implemented; known: signorini");
  const double extra_gap = card.real("gap", 0.0);
  if (!(std::isfinite(extra_gap) && extra_gap >= 0)) card.fail("gap", "must be >= 0");
  const std::unique_ptr<Obstacle> obstacle = obstacle_from_card(card);

  // A node starting inside the obstacle is a geometric error of this card's obstacle.
  try {
    return build_contact_elements(mesh, static_cast<int>(ref), *obstacle, extra_gap, 1.0);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    card.fail("obstacle", e.what());
  }
}

} // namespace sig
