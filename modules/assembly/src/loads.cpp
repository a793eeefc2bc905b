#include "assembly/loads.hpp"

#include "assembly/cards.hpp"
#include "assembly/p1.hpp"
#include "assembly/time_loads.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sig {

namespace {

// The triangles on each side of every mesh edge, to find the sub-domain (thickness) and the
// outward side of a referenced edge.
class EdgeOwners {
public:
  struct Sides {
    int first = -1;  ///< a triangle with this edge
    int second = -1; ///< the other one, -1 on the boundary
  };
  explicit EdgeOwners(const Mesh& mesh) {
    owners_.reserve(3 * mesh.cells.size());
    for (int t = 0; t < mesh.num_cells(); ++t)
      for (int i = 0; i < 3; ++i) {
        Sides& sides = owners_[edge_key(mesh.cells[t][i], mesh.cells[t][(i + 1) % 3])];
        (sides.first < 0 ? sides.first : sides.second) = t;
      }
  }
  /// Triangles on the edge; sig::Error if none.
  const Sides& of(int a, int b) const {
    const auto it = owners_.find(edge_key(a, b));
    SIG_VERIFY(it != owners_.end(),
               "referenced edge (" << a + 1 << ", " << b + 1 << ") is the side of no triangle");
    return it->second;
  }

private:
  std::unordered_map<std::uint64_t, Sides> owners_;
};

Eigen::Vector2d right_normal(const Mesh& mesh, const Facet& edge) {
  const Eigen::Vector2d t = mesh.nodes[edge.node[1]] - mesh.nodes[edge.node[0]];
  return Eigen::Vector2d(t.y(), -t.x()).normalized();
}

Eigen::Vector2d outward_normal(const Mesh& mesh, const EdgeOwners& owners, const Facet& edge) {
  const EdgeOwners::Sides& sides = owners.of(edge.node[0], edge.node[1]);
  Eigen::Vector2d n = right_normal(mesh, edge);
  if (sides.second >= 0) return n;
  const auto& tri = mesh.cells[sides.first];
  const Eigen::Vector2d centroid =
      (mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]) / 3.0;
  if (n.dot(centroid - mesh.nodes[edge.node[0]]) > 0.0) n = -n;
  return n;
}

Eigen::Vector2d card_vector(const Card& card, const std::string& field) {
  const std::vector<double> v = card.reals(field);
  if (v.size() != 2) card.fail(field, "expected two components, e.g. 0,-1");
  return Eigen::Vector2d(v[0], v[1]);
}

void add_edge_load(const Mesh& mesh, const MaterialTable& table, const EdgeOwners& owners,
                   const Facet& edge, const Eigen::Vector2d& traction, Eigen::VectorXd& f) {
  const int owner = owners.of(edge.node[0], edge.node[1]).first;
  const double thickness = table.of(mesh.subdomain[owner]).thickness;
  const Eigen::Vector4d fe =
      p1_edge_load(mesh.nodes[edge.node[0]], mesh.nodes[edge.node[1]], traction, thickness);
  f.segment<2>(2 * edge.node[0]) += fe.head<2>();
  f.segment<2>(2 * edge.node[1]) += fe.tail<2>();
}

// The MOVINGLOAD card, its quadrature laid out on the edges of its references.
MovingLoad moving_load(const Card& card, const Mesh& mesh, const MaterialTable& table,
                       const EdgeOwners& owners) {
  MovingLoad load;
  load.F = card.real("F");
  load.psi = card.real("psi");
  load.c = card.real("c");
  load.x0 = card.real("x0");
  if (!(load.psi > 0)) {
    std::ostringstream what;
    what << "must be > 0 (the Gaussian's decay, per unit length squared: m^-2 in the thesis's "
            "units), got "
         << load.psi;
    card.fail("psi", what.str());
  }
  for (int ref : card_references(card, mesh, RefSupport::edges))
    for (const Facet& edge : mesh.facets_with_ref(ref))
      load.add_edge(
          edge.node[0], edge.node[1], mesh.nodes[edge.node[0]], mesh.nodes[edge.node[1]],
          table.of(mesh.subdomain[owners.of(edge.node[0], edge.node[1]).first]).thickness);
  return load;
}

} // namespace

Eigen::Vector2d edge_outward_normal(const Mesh& mesh, const Facet& edge) {
  return outward_normal(mesh, EdgeOwners(mesh), edge);
}

LoadTarget load_target(const Card& card, Eigen::VectorXd& f, Eigen::VectorXd& rate) {
  // A ramped card adds g / ramp to the rate (nothing at t = 0), a constant one g to f.
  if (!card.has("ramp")) return {f, 1.0};
  const double ramp = card.real("ramp");
  if (!(ramp > 0) || !std::isfinite(ramp))
    card.fail("ramp", "the time at which the ramped load reaches its value must be > 0");
  return {rate, 1.0 / ramp};
}

const Card* ramped_load_card(const Datafile& datafile) {
  for (const char* keyword : {"TRACTION", "PRESSURE", "BODYFORCE"})
    for (const Card* card : datafile.all(keyword))
      if (card->has("ramp")) return card;
  return nullptr;
}

Eigen::VectorXd assemble_loads(const Mesh& mesh, const MaterialTable& table,
                               const Datafile& datafile, TimeLoads* time_loads) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  const auto target = [&](const Card& card) { return load_target(card, f, rate); };
  // No card's load may overflow: the error names the card, where the TAE's would not.
  const auto finite = [](const Card& card, const char* field, const Eigen::VectorXd& load) {
    if (!load.allFinite())
      card.fail(field, "the load it adds is not finite (a value near the largest double): "
                       "check its magnitude and the deck's units");
  };
  const auto traction_cards = datafile.all("TRACTION");
  const auto pressure_cards = datafile.all("PRESSURE");
  const auto moving_cards = datafile.all("MOVINGLOAD");
  if (!traction_cards.empty() || !pressure_cards.empty() || !moving_cards.empty()) {
    const EdgeOwners owners(mesh);
    for (const Card* card : traction_cards) {
      const auto [into, scale] = target(*card);
      const Eigen::Vector2d traction = scale * card_vector(*card, "f");
      for (int ref : card_references(*card, mesh, RefSupport::edges))
        for (const Facet& edge : mesh.facets_with_ref(ref))
          add_edge_load(mesh, table, owners, edge, traction, into);
      finite(*card, "f", into);
    }
    for (const Card* card : pressure_cards) {
      const auto [into, scale] = target(*card);
      const double p = scale * card->real("p");
      for (int ref : card_references(*card, mesh, RefSupport::edges))
        for (const Facet& edge : mesh.facets_with_ref(ref))
          add_edge_load(mesh, table, owners, edge, -p * outward_normal(mesh, owners, edge), into);
      finite(*card, "p", into);
    }
    for (const Card* card : moving_cards) {
      MovingLoad load = moving_load(*card, mesh, table, owners);
      load.add(0.0, f);
      if (time_loads != nullptr) time_loads->moving.push_back(std::move(load));
    }
  }
  for (const Card* card : datafile.all("BODYFORCE")) {
    const auto [into, scale] = target(*card);
    const Eigen::Vector2d force = scale * card_vector(*card, "f");
    const std::vector<int> regions = card_regions(*card, mesh);
    for (int t = 0; t < mesh.num_cells(); ++t) {
      if (std::find(regions.begin(), regions.end(), mesh.subdomain[t]) == regions.end()) continue;
      const Vector6d fe = p1_body_load(p1_area(triangle_vertices(mesh, t)), force,
                                       table.of(mesh.subdomain[t]).thickness);
      for (int i = 0; i < 3; ++i)
        into.segment<2>(2 * mesh.cells[t][i]) += fe.segment<2>(2 * i);
    }
    finite(*card, "f", into);
  }
  if (time_loads != nullptr && (rate.array() != 0).any()) time_loads->rate = std::move(rate);
  return f;
}

} // namespace sig
