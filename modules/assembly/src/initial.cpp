#include "assembly/initial.hpp"

#include "assembly/cards.hpp"
#include "core/datafile.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace sig {

namespace {
/// The vector field `name` of `card`, `d` components (the mesh's dimension), zero if absent.
Eigen::VectorXd vector_field(const Card& card, const std::string& name, int d) {
  if (!card.has(name)) return Eigen::VectorXd::Zero(d);
  const std::vector<double> values = card.reals(name);
  if (static_cast<int>(values.size()) != d)
    card.fail(name, d == 3 ? "expected three components x,y,z (the mesh is 3D)"
                           : "expected two components x,y");
  return Eigen::Map<const Eigen::VectorXd>(values.data(), d);
}

/// The rigid rotation's velocity omega x r at the offset r from the centre: in 2D omega is the
/// scalar rate about e3, omega (-r2, r1); in 3D the vector omega, omega x r.
Eigen::VectorXd rotation_velocity(const Eigen::VectorXd& omega, const Eigen::VectorXd& r) {
  if (r.size() == 2) return omega[0] * Eigen::Vector2d(-r.y(), r.x());
  return Eigen::Vector3d(omega.head<3>()).cross(Eigen::Vector3d(r.head<3>()));
}
} // namespace

InitialFields initial_fields(const Datafile& datafile, const Mesh& mesh) {
  const int d = mesh.dim;
  InitialFields fields{Eigen::VectorXd::Zero(d * mesh.num_nodes()),
                       Eigen::VectorXd::Zero(d * mesh.num_nodes())};
  for (const Card* card : datafile.all("INITIAL")) {
    const Eigen::VectorXd u = vector_field(*card, "u", d);
    const Eigen::VectorXd v = vector_field(*card, "v", d);
    // omega: the rate about e3 in 2D, the angular velocity vector in 3D.
    const Eigen::VectorXd omega = d == 2 ? Eigen::VectorXd::Constant(1, card->real("omega", 0.0))
                                         : vector_field(*card, "omega", d);
    if (card->has("omega") && !card->has("centre"))
      card->fail("omega", d == 3 ? "a rotation needs its centre: give centre=x,y,z"
                                 : "a rotation needs its centre: give centre=x,y");
    if (card->has("centre") && !card->has("omega"))
      card->fail("centre", "is the centre of the rotation omega=: give omega= too");
    const Eigen::VectorXd centre = vector_field(*card, "centre", d);
    const bool velocity = card->has("v") || card->has("omega");
    const std::vector<int> regions = card_regions(*card, mesh);
    for (int t = 0; t < mesh.num_cells(); ++t) {
      if (std::find(regions.begin(), regions.end(), mesh.subdomain[t]) == regions.end()) continue;
      for (int node : mesh.cells[t]) {
        if (card->has("u")) fields.u.segment(d * node, d) = u;
        // v + omega x (X - centre), on the reference position X.
        if (velocity)
          fields.v.segment(d * node, d) = v + rotation_velocity(omega, mesh.nodes[node] - centre);
      }
    }
  }
  return fields;
}

} // namespace sig
