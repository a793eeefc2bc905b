// The load vector of a 3D body (issue 26): TRACTION and PRESSURE on referenced faces, BODYFORCE
// on sub-domains, each the exact integral of the constant load against the P1 basis. A 3D deck
// has no thickness; ramp= as in 2D (assembly/loads.hpp), MOVINGLOAD is 2D only for now.
#include "assembly/cards.hpp"
#include "assembly/loads.hpp"
#include "assembly/p1_simplex.hpp"
#include "assembly/time_loads.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_card.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace sig {
namespace {

Eigen::Vector3d card_vector_3d(const Card& card, const std::string& field) {
  const std::vector<double> v = card.reals(field);
  if (v.size() != 3) card.fail(field, "expected three components in a 3D deck, e.g. 0,0,-1");
  return {v[0], v[1], v[2]};
}

/// (x1 - x0) x (x2 - x0) of a face: its normal times twice its area, outward on the boundary
/// (the mesh readers orient boundary faces so, mesh/topology.hpp).
Eigen::Vector3d face_area_vector(const Mesh& mesh, const Facet& face) {
  const Eigen::Vector3d x0 = mesh.nodes[face.node[0]];
  return (Eigen::Vector3d(mesh.nodes[face.node[1]]) - x0)
      .cross(Eigen::Vector3d(mesh.nodes[face.node[2]]) - x0);
}

/// g |face| / 3 at each of its nodes.
void add_face_load(const Facet& face, double area, const Eigen::Vector3d& traction,
                   Eigen::VectorXd& f) {
  for (int v : face.node)
    f.segment<3>(3 * v) += traction * (area / 3.0);
}

void finite(const Card& card, const char* field, const Eigen::VectorXd& load) {
  if (!load.allFinite())
    card.fail(field, "the load it adds is not finite (a value near the largest double): check "
                     "its magnitude and the deck's units");
}

} // namespace

Eigen::VectorXd assemble_loads_3d(const Mesh& mesh, const Datafile& datafile,
                                  TimeLoads* time_loads) {
  SIG_VERIFY(mesh.dim == 3, "assemble_loads_3d: the mesh is " << mesh.dim << "D");
  for (const Card* moving : datafile.all("MOVINGLOAD"))
    moving->fail("ref", "a moving load in 3D is not implemented yet (issue 26)");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (const Card* card : datafile.all("TRACTION")) {
    const auto [into, scale] = load_target(*card, f, rate);
    const Eigen::Vector3d traction = scale * card_vector_3d(*card, "f");
    for (int ref : card_references(*card, mesh, RefSupport::edges))
      for (const Facet& face : mesh.facets_with_ref(ref))
        add_face_load(face, 0.5 * face_area_vector(mesh, face).norm(), traction, into);
    finite(*card, "f", into);
  }
  for (const Card* card : datafile.all("PRESSURE")) {
    const auto [into, scale] = load_target(*card, f, rate);
    const double p = scale * card->real("p");
    for (int ref : card_references(*card, mesh, RefSupport::edges))
      for (const Facet& face : mesh.facets_with_ref(ref)) {
        const Eigen::Vector3d n = face_area_vector(mesh, face);
        add_face_load(face, 0.5 * n.norm(), -p * n.normalized(), into);
      }
    finite(*card, "p", into);
  }
  for (const Card* card : datafile.all("BODYFORCE")) {
    const auto [into, scale] = load_target(*card, f, rate);
    const Eigen::Vector3d force = scale * card_vector_3d(*card, "f");
    const std::vector<int> regions = card_regions(*card, mesh);
    for (int t = 0; t < mesh.num_cells(); ++t) {
      if (std::find(regions.begin(), regions.end(), mesh.subdomain[t]) == regions.end()) continue;
      const SimplexVector<3> fe =
          p1_simplex_body_load<3>(p1_measure<3>(simplex_vertices<3>(mesh, t)), force, 1.0);
      for (int i = 0; i < 4; ++i)
        into.segment<3>(3 * mesh.cells[t][i]) += fe.segment<3>(3 * i);
    }
    finite(*card, "f", into);
  }
  if (time_loads != nullptr && (rate.array() != 0).any()) time_loads->rate = std::move(rate);
  return f;
}

} // namespace sig
