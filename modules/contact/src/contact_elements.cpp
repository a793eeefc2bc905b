#include "contact/contact_elements.hpp"

#include "core/error.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace sig {

namespace {

// Roundoff allowed on the gap of a node lying on the obstacle, relative to the shortest Gamma3
// edge: below it a negative gap is set to 0, beyond it the node starts inside the obstacle.
constexpr double kRoundoffGap = 1e-9;

// The Gamma3 facets without repetition (an interface facet may be stored from both sides); the
// first stored orientation is kept.
std::vector<Facet> unique_facets(const Mesh& mesh, int ref) {
  std::vector<Facet> facets;
  std::set<std::array<int, 3>> seen;
  for (const Facet& f : mesh.facets) {
    if (f.ref != ref) continue;
    std::array<int, 3> key{-1, -1, -1}; // an edge's third entry stays -1
    for (int k = 0; k < std::min(f.node.size(), 3); ++k)
      key[k] = f.node[k];
    std::sort(key.begin(), key.end());
    if (seen.insert(key).second) facets.push_back(f);
  }
  return facets;
}

// The measure of a facet (length of an edge, area of a face) and its outward normal scaled by
// that measure (2D: the edge a -> b turned clockwise, the domain on its left; 3D: the right-hand
// rule of mesh.hpp's Facet).
double facet_measure(const Mesh& mesh, const Facet& f) {
  const Point& a = mesh.nodes[f.node[0]];
  if (mesh.dim == 2) return (mesh.nodes[f.node[1]] - a).norm();
  const Eigen::Vector3d ab = mesh.nodes[f.node[1]] - a, ac = mesh.nodes[f.node[2]] - a;
  return 0.5 * ab.cross(ac).norm();
}

Point outward_normal(const Mesh& mesh, const Facet& f) {
  const Point& a = mesh.nodes[f.node[0]];
  if (mesh.dim == 2) {
    const Point d = mesh.nodes[f.node[1]] - a;
    return Point(d.y(), -d.x());
  }
  const Eigen::Vector3d ab = mesh.nodes[f.node[1]] - a, ac = mesh.nodes[f.node[2]] - a;
  return Point(0.5 * ab.cross(ac));
}

// The shortest side of the facets: the length roundoff is measured against.
double shortest_side(const Mesh& mesh, const std::vector<Facet>& facets) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Facet& f : facets)
    for (int a = 0; a < f.node.size(); ++a)
      for (int b = a + 1; b < f.node.size(); ++b)
        shortest = std::min(shortest, (mesh.nodes[f.node[b]] - mesh.nodes[f.node[a]]).norm());
  return shortest;
}

// The nodes of `edges` along the boundary chains they form (see build_contact_elements).
std::vector<int> nodes_along_boundary(const std::vector<Facet>& edges) {
  std::map<int, std::vector<int>> neighbours; // sorted by node number
  std::set<std::pair<int, int>> forward;      // (a, b) as stored
  for (const Facet& e : edges) {
    neighbours[e.node[0]].push_back(e.node[1]);
    neighbours[e.node[1]].push_back(e.node[0]);
    forward.insert({e.node[0], e.node[1]});
  }
  std::vector<int> order;
  for (const auto& [v, nb] : neighbours)
    if (nb.size() > 2) {
      for (const auto& entry : neighbours)
        order.push_back(entry.first);
      return order;
    }

  std::set<int> visited;
  const auto walk = [&](int start, int second) {
    int previous = start, current = second;
    order.push_back(start);
    visited.insert(start);
    while (current >= 0 && !visited.count(current)) {
      order.push_back(current);
      visited.insert(current);
      int next = -1;
      for (int candidate : neighbours.at(current))
        if (candidate != previous) next = candidate;
      previous = current;
      current = next;
    }
  };
  // One chain per connected component, components by their smallest node number. An open
  // chain starts at the end whose edge leaves it (boundary direction), else at its smaller end.
  for (const auto& [v, nb] : neighbours) {
    if (visited.count(v)) continue;
    std::vector<int> stack{v}, ends;
    std::set<int> component{v};
    while (!stack.empty()) {
      const int w = stack.back();
      stack.pop_back();
      if (neighbours.at(w).size() == 1) ends.push_back(w);
      for (int x : neighbours.at(w))
        if (component.insert(x).second) stack.push_back(x);
    }
    int start = *component.begin(); // closed chain: its smallest node
    if (!ends.empty()) {
      std::sort(ends.begin(), ends.end());
      const auto leaving = std::find_if(ends.begin(), ends.end(), [&](int end) {
        return forward.count({end, neighbours.at(end).front()}) > 0;
      });
      start = leaving != ends.end() ? *leaving : ends.front();
    }
    int second = neighbours.at(start).front();
    for (int candidate : neighbours.at(start))
      if (forward.count({start, candidate})) second = candidate;
    walk(start, second);
  }
  return order;
}

} // namespace

bool ContactElements::has_friction() const {
  return any_friction(law);
}

double ContactElements::bound(int i) const {
  return law[i].has_wall() ? gap[i] + law[i].depth : std::numeric_limits<double>::infinity();
}

ContactElements ContactElements::subset(const std::vector<int>& zone) const {
  ContactElements part = *this;
  part.node.clear();
  part.lagrange_node.clear();
  part.normal.clear();
  part.tangent.clear();
  part.law.clear();
  part.gap.resize(static_cast<Eigen::Index>(zone.size()));
  part.weight.resize(static_cast<Eigen::Index>(zone.size()));
  for (std::size_t k = 0; k < zone.size(); ++k) {
    const int i = zone[k];
    part.node.push_back(node[i]);
    part.lagrange_node.push_back(lagrange_node[i]);
    part.normal.push_back(normal[i]);
    part.tangent.push_back(tangent[i]);
    part.law.push_back(law[i]);
    part.gap[static_cast<Eigen::Index>(k)] = gap[i];
    part.weight[static_cast<Eigen::Index>(k)] = weight[i];
  }
  return part;
}

std::vector<ContactFrame> ContactElements::frames() const {
  std::vector<ContactFrame> R;
  R.reserve(normal.size());
  for (int i = 0; i < size(); ++i)
    R.push_back(frame(i));
  return R;
}

ContactElements build_contact_elements(const Mesh& mesh, int ref, const Obstacle& obstacle,
                                       const ContactLaw& law, double thickness,
                                       const std::vector<int>& excluded) {
  SIG_VERIFY(std::isfinite(thickness) && thickness > 0,
             "contact elements: thickness " << thickness << " must be > 0");
  const std::optional<LawProblem> inadmissible = law_problem(law);
  SIG_VERIFY(!inadmissible,
             "contact elements: " << inadmissible->field << " " << inadmissible->what);
  SIG_VERIFY(obstacle.dim() == mesh.dim, "contact elements: a "
                                             << obstacle.dim() << "D " << obstacle.kind()
                                             << " obstacle for a " << mesh.dim << "D mesh");
  const std::vector<Facet> facets = unique_facets(mesh, ref);
  SIG_VERIFY(!facets.empty(),
             "contact elements: no mesh " << mesh.facet_name() << " carries reference " << ref);

  // Tributary weights: each Gamma3 facet gives its measure over its d nodes to each of them.
  std::map<int, double> weight_of;
  for (const Facet& f : facets) {
    std::set<int> distinct;
    for (int k : f.node) {
      SIG_VERIFY(k >= 0 && k < mesh.num_nodes() && distinct.insert(k).second,
                 "contact elements: a " << mesh.facet_name() << " with reference " << ref
                                        << " has an invalid or repeated node " << k + 1);
    }
    const double share = facet_measure(mesh, f) / mesh.dim * (mesh.dim == 2 ? thickness : 1.0);
    for (int k : f.node)
      weight_of[k] += share;
  }
  const double shortest = shortest_side(mesh, facets);

  ContactElements elements;
  elements.dim = mesh.dim;
  elements.num_nodes = mesh.num_nodes();
  elements.ref = ref;
  elements.thickness = thickness;
  elements.obstacle = obstacle.description();
  if (mesh.dim == 2) {
    elements.node = nodes_along_boundary(facets);
  } else {
    for (const auto& entry : weight_of)
      elements.node.push_back(entry.first);
  }
  const std::set<int> skip(excluded.begin(), excluded.end());
  std::erase_if(elements.node, [&](int k) { return skip.count(k) > 0; });
  SIG_VERIFY(!elements.node.empty(),
             "contact elements: every node of reference " << ref << " is excluded");
  const int m = elements.size();
  elements.gap.resize(m);
  elements.weight.resize(m);
  for (int i = 0; i < m; ++i) {
    const int k = elements.node[i];
    const Point& x = mesh.nodes[k];
    double distance = obstacle.signed_distance(x);
    SIG_VERIFY(distance >= -kRoundoffGap * shortest,
               "contact elements: node " << k + 1 << " " << coordinates(x) << " starts inside the "
                                         << obstacle.kind() << " obstacle (signed distance "
                                         << distance << ")");
    distance = std::max(distance, 0.0);
    elements.lagrange_node.push_back(elements.num_nodes + i);
    elements.normal.push_back(obstacle.normal(x));
    elements.tangent.push_back(Point(elements.frame(i).col(0)));
    elements.gap(i) = distance;
    elements.weight(i) = weight_of.at(k);
    elements.law.push_back(law);
  }
  return elements;
}

std::vector<int> nodes_facing_away(const Mesh& mesh, const ContactElements& elements) {
  std::map<int, Point> outward;
  for (const Facet& f : unique_facets(mesh, elements.ref)) {
    const Point n = outward_normal(mesh, f);
    for (int k : f.node)
      outward.try_emplace(k, Point(Point::Zero(mesh.dim))).first->second += n;
  }
  std::vector<int> away;
  for (int i = 0; i < elements.size(); ++i)
    if (elements.normal[i].dot(outward.at(elements.node[i])) > 0) away.push_back(i);
  return away;
}

Eigen::SparseMatrix<double> normal_operator(const ContactElements& elements, int ndof) {
  const int d = elements.dim;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(d) * elements.size());
  for (int i = 0; i < elements.size(); ++i) {
    const int k = elements.node[i];
    SIG_VERIFY(k >= 0 && d * k + d - 1 < ndof,
               "normal operator: contact node " << k + 1 << " has no dofs among " << ndof);
    for (int c = 0; c < d; ++c)
      entries.emplace_back(i, d * k + c, -elements.normal[i][c]);
  }
  Eigen::SparseMatrix<double> b_n(elements.size(), ndof);
  b_n.setFromTriplets(entries.begin(), entries.end());
  return b_n;
}

} // namespace sig
