// The boundary test of same_domain.hpp: the boundary sides of each mesh sampled into a grid of
// cells as wide as the tolerance, each boundary node of the other mesh checked against the sides
// near it.
#include "post/same_domain.hpp"

#include "mesh/topology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sig {

namespace {

struct Segment {
  Eigen::Vector2d a, b;
};

/// The sides of one triangle only.
std::vector<Segment> boundary(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, int> uses;
  for (const auto& tri : mesh.cells)
    for (int j = 0; j < 3; ++j)
      ++uses[edge_key(tri[j], tri[(j + 1) % 3])];
  std::vector<Segment> sides;
  for (const auto& tri : mesh.cells)
    for (int j = 0; j < 3; ++j)
      if (uses[edge_key(tri[j], tri[(j + 1) % 3])] == 1)
        sides.push_back({mesh.nodes[tri[j]], mesh.nodes[tri[(j + 1) % 3]]});
  return sides;
}

double distance(const Eigen::Vector2d& x, const Segment& s) {
  const Eigen::Vector2d d = s.b - s.a;
  const double t = std::clamp((x - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (x - (s.a + t * d)).norm();
}

/// The sides of a boundary by the cells of width `cell` their points pass through.
class SideGrid {
public:
  SideGrid(std::vector<Segment> sides, double cell) : sides_(std::move(sides)), cell_(cell) {
    for (int k = 0; k < static_cast<int>(sides_.size()); ++k) {
      const Segment& s = sides_[k];
      const int samples = 1 + static_cast<int>(2 * (s.b - s.a).norm() / cell_);
      for (int i = 0; i <= samples; ++i) {
        std::vector<int>& here = cells_[key(s.a + (s.b - s.a) * (double(i) / samples))];
        if (here.empty() || here.back() != k) here.push_back(k);
      }
    }
  }
  /// Whether a side lies within `cell` of x (sample points are cell / 2 apart: a side that
  /// close has one within 2 cells of x's).
  bool near(const Eigen::Vector2d& x) const {
    const auto [i, j] = index(x);
    for (long di = -2; di <= 2; ++di)
      for (long dj = -2; dj <= 2; ++dj)
        if (const auto it = cells_.find(pack(i + di, j + dj)); it != cells_.end())
          for (int k : it->second)
            if (distance(x, sides_[k]) <= cell_) return true;
    return false;
  }
  double nearest(const Eigen::Vector2d& x) const {
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& s : sides_)
      best = std::min(best, distance(x, s));
    return best;
  }

private:
  std::pair<long, long> index(const Eigen::Vector2d& x) const {
    return {std::lround(std::floor(x.x() / cell_)), std::lround(std::floor(x.y() / cell_))};
  }
  static std::uint64_t pack(long i, long j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) |
           static_cast<std::uint32_t>(j);
  }
  std::uint64_t key(const Eigen::Vector2d& x) const {
    const auto [i, j] = index(x);
    return pack(i, j);
  }
  std::vector<Segment> sides_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

double size_of(const Mesh& mesh) {
  Eigen::Vector2d low = mesh.nodes.front(), high = low;
  for (const Point& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  return (high - low).norm();
}

} // namespace

std::string domain_mismatch(const Mesh& mesh, const std::string& mesh_name, const Mesh& reference,
                            const std::string& reference_name) {
  const double size = size_of(reference);
  const double tolerance = kDomainTolerance * size;
  const std::vector<Segment> sides[2] = {boundary(mesh), boundary(reference)};
  const SideGrid grids[2] = {{sides[0], tolerance}, {sides[1], tolerance}};
  const std::string names[2] = {mesh_name, reference_name};
  for (int m = 0; m < 2; ++m)
    for (const Segment& s : sides[m])
      if (!grids[1 - m].near(s.a)) {
        std::ostringstream why;
        why << names[0] << " and " << names[1]
            << " are not meshes of one domain: the boundary node (" << s.a.x() << ", " << s.a.y()
            << ") of " << names[m] << " lies " << grids[1 - m].nearest(s.a)
            << " from the boundary of " << names[1 - m] << ", more than " << 100 * kDomainTolerance
            << " % of the reference's size " << size
            << " (two meshes of one domain differ on its boundary by their discretization "
               "only)";
        return why.str();
      }
  return "";
}

} // namespace sig
