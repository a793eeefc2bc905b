#include "contact/contact_elements.hpp"

#include "core/error.hpp"

#include <algorithm>
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

// The Gamma3 edges without repetition (an interface edge may be stored from both sides); the
// first stored direction is kept.
std::vector<Facet> unique_edges(const Mesh& mesh, int ref) {
  std::vector<Facet> edges;
  std::set<std::pair<int, int>> seen;
  for (const Facet& e : mesh.facets) {
    if (e.ref != ref) continue;
    if (seen.insert({std::min(e.node[0], e.node[1]), std::max(e.node[0], e.node[1])}).second)
      edges.push_back(e);
  }
  return edges;
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

ContactElements build_contact_elements(const Mesh& mesh, int ref, const Obstacle& obstacle,
                                       const ContactLaw& law, double thickness,
                                       const std::vector<int>& excluded) {
  SIG_VERIFY(std::isfinite(thickness) && thickness > 0,
             "contact elements: thickness " << thickness << " must be > 0");
  const std::optional<LawProblem> inadmissible = law_problem(law);
  SIG_VERIFY(!inadmissible,
             "contact elements: " << inadmissible->field << " " << inadmissible->what);
  const std::vector<Facet> edges = unique_edges(mesh, ref);
  SIG_VERIFY(!edges.empty(), "contact elements: no mesh edge carries reference " << ref);

  // Tributary weights: each Gamma3 edge gives half its length to each end node.
  std::map<int, double> weight_of;
  double shortest = std::numeric_limits<double>::infinity();
  for (const Facet& e : edges) {
    SIG_VERIFY(e.node[0] >= 0 && e.node[0] < mesh.num_nodes() && e.node[1] >= 0 &&
                   e.node[1] < mesh.num_nodes() && e.node[0] != e.node[1],
               "contact elements: edge (" << e.node[0] + 1 << ", " << e.node[1] + 1
                                          << ") with reference " << ref << " is invalid");
    const double length = (mesh.nodes[e.node[1]] - mesh.nodes[e.node[0]]).norm();
    weight_of[e.node[0]] += 0.5 * length * thickness;
    weight_of[e.node[1]] += 0.5 * length * thickness;
    shortest = std::min(shortest, length);
  }

  ContactElements elements;
  elements.num_nodes = mesh.num_nodes();
  elements.ref = ref;
  elements.thickness = thickness;
  elements.obstacle = obstacle.description();
  elements.node = nodes_along_boundary(edges);
  const std::set<int> skip(excluded.begin(), excluded.end());
  std::erase_if(elements.node, [&](int k) { return skip.count(k) > 0; });
  SIG_VERIFY(!elements.node.empty(),
             "contact elements: every node of reference " << ref << " is excluded");
  const int m = elements.size();
  elements.gap.resize(m);
  elements.weight.resize(m);
  for (int i = 0; i < m; ++i) {
    const int k = elements.node[i];
    const Eigen::Vector2d& x = mesh.nodes[k];
    double distance = obstacle.signed_distance(x);
    SIG_VERIFY(distance >= -kRoundoffGap * shortest,
               "contact elements: node " << k + 1 << " (" << x.x() << ", " << x.y()
                                         << ") starts inside the " << obstacle.kind()
                                         << " obstacle (signed distance " << distance << ")");
    distance = std::max(distance, 0.0);
    elements.lagrange_node.push_back(elements.num_nodes + i);
    elements.normal.push_back(obstacle.normal(x));
    elements.tangent.push_back(contact_tangent(elements.normal.back()));
    elements.gap(i) = distance;
    elements.weight(i) = weight_of.at(k);
    elements.law.push_back(law);
  }
  return elements;
}

std::vector<int> nodes_facing_away(const Mesh& mesh, const ContactElements& elements) {
  // The stored edges have the domain on their left: the outward normal of a -> b is the
  // direction b - a turned clockwise.
  std::map<int, Eigen::Vector2d> outward;
  for (const Facet& e : unique_edges(mesh, elements.ref)) {
    const Eigen::Vector2d d = mesh.nodes[e.node[1]] - mesh.nodes[e.node[0]];
    const Eigen::Vector2d n(d.y(), -d.x());
    for (int k : {e.node[0], e.node[1]})
      outward.try_emplace(k, Eigen::Vector2d::Zero()).first->second += n;
  }
  std::vector<int> away;
  for (int i = 0; i < elements.size(); ++i)
    if (elements.normal[i].dot(outward.at(elements.node[i])) > 0) away.push_back(i);
  return away;
}

Eigen::SparseMatrix<double> normal_operator(const ContactElements& elements, int ndof) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(2 * elements.size());
  for (int i = 0; i < elements.size(); ++i) {
    const int k = elements.node[i];
    SIG_VERIFY(k >= 0 && 2 * k + 1 < ndof,
               "normal operator: contact node " << k + 1 << " has no dofs among " << ndof);
    entries.emplace_back(i, 2 * k, -elements.normal[i].x());
    entries.emplace_back(i, 2 * k + 1, -elements.normal[i].y());
  }
  Eigen::SparseMatrix<double> b_n(elements.size(), ndof);
  b_n.setFromTriplets(entries.begin(), entries.end());
  return b_n;
}

} // namespace sig
