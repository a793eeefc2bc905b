#include "integrator/time_card.hpp"

#include "assembly/cards.hpp"
#include "core/datafile.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace sig {

namespace {
Eigen::Vector2d vector_field(const Card& card, const std::string& name) {
  if (!card.has(name)) return Eigen::Vector2d::Zero();
  const std::vector<double> values = card.reals(name);
  if (values.size() != 2) card.fail(name, "expected two components x,y");
  return {values[0], values[1]};
}
} // namespace

TimeParameters time_parameters(const Card& time, bool has_contact) {
  TimeParameters p;
  p.scheme = time.choice("scheme", {"midpoint", "newmark"});
  p.final_time = time.real("T");
  p.k = time.real("k");
  if (p.k <= 0) time.fail("k", "the time step must be positive");
  if (p.final_time <= 0) time.fail("T", "the final time must be positive");
  // A step count that is not whole would make the last step end before or after T.
  const double ratio = p.final_time / p.k;
  if (ratio > 1e9) time.fail("k", "T / k is more than 1e9 steps");
  const double steps = std::round(ratio);
  if (steps < 1 || std::abs(ratio - steps) > 1e-9 * ratio) {
    std::ostringstream what;
    what << "T / k = " << ratio << " is not a whole number of steps";
    time.fail("k", what.str());
  }
  p.steps = static_cast<int>(steps);
  const long every = time.integer("output_every", 1);
  if (every < 1) time.fail("output_every", "must be >= 1");
  p.output_every = static_cast<int>(std::min<long>(every, p.steps));
  const std::string mass = time.choice("mass", {"consistent", "lumped", "emm"}, "consistent");
  if (mass == "emm" && !has_contact)
    time.fail("mass", "mass=emm needs a CONTACT card: the Equivalent Mass Matrix (3.54) removes "
                      "the normal inertia of the contact nodes of Gamma3");
  p.mass = mass_choice_from_string(mass);
  return p;
}

InitialFields initial_fields(const Datafile& datafile, const Mesh& mesh) {
  InitialFields fields{Eigen::VectorXd::Zero(2 * mesh.num_nodes()),
                       Eigen::VectorXd::Zero(2 * mesh.num_nodes())};
  for (const Card* card : datafile.all("INITIAL")) {
    const Eigen::Vector2d u = vector_field(*card, "u");
    const Eigen::Vector2d v = vector_field(*card, "v");
    const std::vector<int> regions = card_regions(*card, mesh);
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      if (std::find(regions.begin(), regions.end(), mesh.subdomain[t]) == regions.end()) continue;
      for (int node : mesh.triangles[t]) {
        if (card->has("u")) fields.u.segment<2>(2 * node) = u;
        if (card->has("v")) fields.v.segment<2>(2 * node) = v;
      }
    }
  }
  return fields;
}

} // namespace sig
