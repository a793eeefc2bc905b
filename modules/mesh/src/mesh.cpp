#include "mesh/mesh.hpp"

#include "core/error.hpp"
#include "core/ranges.hpp"
#include "mesh/topology.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace sig {
namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

std::vector<int> Mesh::nodes_with_ref(int ref) const {
  std::vector<int> result;
  for (const auto& f : facets) {
    if (f.ref == ref) result.insert(result.end(), f.node.begin(), f.node.end());
  }
  for (std::size_t i = 0; i < vertex_ref.size(); ++i) {
    if (vertex_ref[i] == ref) result.push_back(static_cast<int>(i));
  }
  sort_unique(result);
  return result;
}

std::vector<Facet> Mesh::facets_with_ref(int ref) const {
  std::vector<Facet> result;
  std::copy_if(facets.begin(), facets.end(), std::back_inserter(result),
               [ref](const Facet& f) { return f.ref == ref; });
  return result;
}

std::vector<int> Mesh::references() const {
  std::vector<int> result;
  for (const auto& f : facets)
    result.push_back(f.ref);
  for (int r : vertex_ref) {
    if (r != 0) result.push_back(r);
  }
  sort_unique(result);
  return result;
}

std::vector<int> Mesh::subdomains() const {
  std::vector<int> result = subdomain;
  sort_unique(result);
  return result;
}

double signed_double_area(const Mesh& mesh, int t) {
  const auto& tri = mesh.cells[t];
  const Eigen::Vector2d u = mesh.nodes[tri[1]] - mesh.nodes[tri[0]];
  const Eigen::Vector2d v = mesh.nodes[tri[2]] - mesh.nodes[tri[0]];
  return u.x() * v.y() - u.y() * v.x();
}

double signed_cell_determinant(const Mesh& mesh, int c) {
  if (mesh.dim == 2) return signed_double_area(mesh, c);
  const auto& tet = mesh.cells[c];
  const Eigen::Vector3d x0 = mesh.nodes[tet[0]];
  Eigen::Matrix3d edges;
  for (int j = 0; j < 3; ++j)
    edges.col(j) = Eigen::Vector3d(mesh.nodes[tet[j + 1]]) - x0;
  return edges.determinant();
}

double diameter(const Mesh& mesh) {
  if (mesh.nodes.empty()) return 0;
  Point low = mesh.nodes.front(), high = low;
  for (const Point& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  return (high - low).norm();
}

std::string coordinates(const Point& x) {
  std::ostringstream out;
  out << "(";
  for (Eigen::Index k = 0; k < x.size(); ++k)
    out << (k ? ", " : "") << x[k];
  out << ")";
  return out.str();
}

void require_2d(const Mesh& mesh, const std::string& stage, const std::string& what) {
  SIG_VERIFY(mesh.dim == 2,
             stage << ": 3D " << what << " is not implemented yet (issue 26): the mesh is 3D");
}

namespace {

// A P1 stiffness of a cell whose longest edge is A times its smallest height has a condition
// number of about A^2: beyond 1e6 it keeps fewer than 4 digits.
constexpr double kMaxAspectRatio = 1e6;

/// The smallest height of cell c: d! |measure| over (d - 1)! times its largest facet's measure.
double smallest_height(const Mesh& mesh, int c, double longest) {
  const double det = signed_cell_determinant(mesh, c);
  if (mesh.dim == 2) return det / longest;
  double largest_face = 0; // twice the area of the largest face
  for (const Simplex& f : outward_facet_array(mesh.cells[c])) {
    const Eigen::Vector3d x0 = mesh.nodes[f[0]];
    const Eigen::Vector3d u = Eigen::Vector3d(mesh.nodes[f[1]]) - x0;
    const Eigen::Vector3d v = Eigen::Vector3d(mesh.nodes[f[2]]) - x0;
    largest_face = std::max(largest_face, u.cross(v).norm());
  }
  return det / largest_face;
}

// The mesh's size and its cells' shapes within what a solve can carry (core/ranges.hpp: the
// magnitudes of the deck's lengths).
void verify_scale(const Mesh& mesh, const std::string& source) {
  for (const Point& x : mesh.nodes)
    for (const double c : x)
      SIG_VERIFY(std::abs(c) <= kLargestMagnitude,
                 source << ": a node at " << coordinates(x) << ": " << magnitude_excess(c));
  const double size = diameter(mesh);
  SIG_VERIFY(magnitude_excess(size).empty(),
             source << ": the mesh spans " << size
                    << " (the diagonal of its bounding box): " << magnitude_excess(size));
  const int n = mesh.dim + 1;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const auto& cell = mesh.cells[t];
    double longest = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        longest = std::max(longest, (mesh.nodes[cell[j]] - mesh.nodes[cell[i]]).norm());
    const double height = smallest_height(mesh, t, longest);
    if (mesh.dim == 2)
      SIG_VERIFY(longest <= kMaxAspectRatio * height,
                 source << ": triangle " << t + 1 << " (1-based) is flat: its longest side, "
                        << longest << ", is " << longest / height << " times its height, more than "
                        << kMaxAspectRatio << " (a P1 stiffness of it would keep no digits)");
    else
      SIG_VERIFY(longest <= kMaxAspectRatio * height,
                 source << ": tetrahedron " << t + 1 << " (1-based) is flat: its longest edge, "
                        << longest << ", is " << longest / height
                        << " times its smallest height, more than " << kMaxAspectRatio
                        << " (a P1 stiffness of it would keep no digits)");
  }
}

} // namespace

void check_mesh(const Mesh& mesh, const std::string& source) {
  SIG_VERIFY(mesh.dim == 2 || mesh.dim == 3,
             source << ": the mesh's dimension is " << mesh.dim << " (2 or 3 expected)");
  const int nn = mesh.num_nodes();
  const int nt = mesh.num_cells();
  const std::string cell = mesh.cell_name();
  SIG_VERIFY(nt > 0, source << ": the mesh has no " << cell);
  SIG_VERIFY(mesh.subdomain.size() == mesh.cells.size(), source << ": " << mesh.subdomain.size()
                                                                << " sub-domain numbers for " << nt
                                                                << " " << cell << "s");
  SIG_VERIFY(mesh.vertex_ref.size() == mesh.nodes.size(), source << ": " << mesh.vertex_ref.size()
                                                                 << " vertex references for " << nn
                                                                 << " nodes");
  for (int i = 0; i < nn; ++i) {
    SIG_VERIFY(mesh.nodes[i].size() == mesh.dim,
               source << ": node " << i + 1 << " (1-based) has " << mesh.nodes[i].size()
                      << " coordinates in a mesh of dimension " << mesh.dim);
    SIG_VERIFY(mesh.nodes[i].allFinite(),
               source << ": node " << i + 1 << " (1-based) has a non-finite coordinate");
    SIG_VERIFY(mesh.vertex_ref[i] >= 0, source << ": node " << i + 1
                                               << " (1-based) has a negative reference "
                                               << mesh.vertex_ref[i]);
  }
  std::vector<char> used(nn, 0);
  for (int t = 0; t < nt; ++t) {
    SIG_VERIFY(mesh.cells[t].size() == mesh.dim + 1, source << ": " << cell << " " << t + 1
                                                            << " (1-based) has "
                                                            << mesh.cells[t].size() << " nodes");
    for (int v : mesh.cells[t]) {
      SIG_VERIFY(v >= 0 && v < nn, source << ": " << cell << " " << t + 1 << " (1-based) uses node "
                                          << v + 1 << ", out of range 1.." << nn);
      used[v] = 1;
    }
    SIG_VERIFY(mesh.subdomain[t] >= 1, source << ": " << cell << " " << t + 1
                                              << " (1-based) has sub-domain " << mesh.subdomain[t]
                                              << " (must be >= 1)");
    if (mesh.dim == 2) {
      const double area = 0.5 * signed_double_area(mesh, t);
      SIG_VERIFY(area > 0, source << ": triangle " << t + 1
                                  << " (1-based) is inverted or degenerate (signed area " << area
                                  << ")");
    } else {
      const double volume = signed_cell_determinant(mesh, t) / 6;
      SIG_VERIFY(volume > 0, source << ": tetrahedron " << t + 1
                                    << " (1-based) is inverted or degenerate (signed volume "
                                    << volume << ")");
    }
  }
  for (int i = 0; i < nn; ++i) {
    SIG_VERIFY(used[i], source << ": node " << i + 1 << " (1-based) is used by no " << cell);
  }
  verify_scale(mesh, source);
  if (const CellOverlap overlap = find_overlap(mesh); overlap.second >= 0)
    SIG_VERIFY(false, source << ": " << overlap.what);
  // The referenced facets' keys, marked when a cell has them as a facet (cells' facets off the
  // referenced nodes skipped unhashed: one pass over the cells, no table of all their facets).
  std::unordered_map<FacetKey, bool, FacetKeyHash> sides;
  sides.reserve(mesh.facets.size());
  for (const Facet& f : mesh.facets)
    if (f.node.size() == mesh.dim) sides.emplace(facet_key(f.node), false);
  const std::vector<char> on = nodes_on_facets(mesh);
  if (!sides.empty())
    for (const auto& c : mesh.cells)
      for (const Simplex& f : outward_facet_array(c))
        if (all_marked(on, f))
          if (const auto it = sides.find(facet_key(f)); it != sides.end()) it->second = true;
  const auto is_side = [&](const Simplex& nodes) {
    const auto it = sides.find(facet_key(nodes));
    return it != sides.end() && it->second;
  };
  const std::string facet = mesh.facet_name();
  for (std::size_t e = 0; e < mesh.facets.size(); ++e) {
    const Facet& f = mesh.facets[e];
    SIG_VERIFY(f.node.size() == mesh.dim, source << ": " << facet << " " << e + 1
                                                 << " (1-based) has " << f.node.size() << " nodes");
    for (int v : f.node)
      SIG_VERIFY(v >= 0 && v < nn, source << ": " << facet << " " << e + 1
                                          << " (1-based) uses a node out of range 1.." << nn);
    SIG_VERIFY(f.ref >= 1, source << ": " << facet << " " << e + 1 << " (1-based) has reference "
                                  << f.ref << " (must be >= 1)");
    if (mesh.dim == 2)
      SIG_VERIFY(is_side(f.node), source << ": edge " << e + 1 << " (1-based) from node "
                                         << f.node[0] + 1 << " to node " << f.node[1] + 1
                                         << " is not a side of any triangle");
    else
      SIG_VERIFY(is_side(f.node), source << ": face " << e + 1 << " (1-based) of nodes "
                                         << f.node[0] + 1 << ", " << f.node[1] + 1 << ", "
                                         << f.node[2] + 1 << " is not a face of any tetrahedron");
  }
}

} // namespace sig
