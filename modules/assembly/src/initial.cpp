#include "assembly/initial.hpp"

#include "assembly/cards.hpp"
#include "core/datafile.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
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

InitialFields initial_fields(const Datafile& datafile, const Mesh& mesh) {
  InitialFields fields{Eigen::VectorXd::Zero(2 * mesh.num_nodes()),
                       Eigen::VectorXd::Zero(2 * mesh.num_nodes())};
  for (const Card* card : datafile.all("INITIAL")) {
    const Eigen::Vector2d u = vector_field(*card, "u");
    const Eigen::Vector2d v = vector_field(*card, "v");
    const double omega = card->real("omega", 0.0);
    if (card->has("omega") && !card->has("centre"))
      card->fail("omega", "a rotation needs its centre: give centre=x,y");
    if (card->has("centre") && !card->has("omega"))
      card->fail("centre", "is the centre of the rotation omega=: give omega= too");
    const Eigen::Vector2d centre = vector_field(*card, "centre");
    const bool velocity = card->has("v") || card->has("omega");
    const std::vector<int> regions = card_regions(*card, mesh);
    for (int t = 0; t < mesh.num_cells(); ++t) {
      if (std::find(regions.begin(), regions.end(), mesh.subdomain[t]) == regions.end()) continue;
      for (int node : mesh.cells[t]) {
        if (card->has("u")) fields.u.segment<2>(2 * node) = u;
        // omega e3 x (X - centre) = omega (-(X2 - c2), X1 - c1), on the reference position.
        const Eigen::Vector2d r = mesh.nodes[node] - centre;
        if (velocity) fields.v.segment<2>(2 * node) = v + omega * Eigen::Vector2d(-r.y(), r.x());
      }
    }
  }
  return fields;
}

} // namespace sig
