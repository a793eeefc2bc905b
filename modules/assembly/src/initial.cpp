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
