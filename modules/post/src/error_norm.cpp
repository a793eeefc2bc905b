// The error in the norm of V of error_norm.hpp: point location of the reference nodes in the
// coarse mesh by a uniform grid of bins, then the P1 interpolation.
#include "post/error_norm.hpp"

#include "assembly/strain.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sig {

namespace {

/// Barycentric coordinates of x in triangle t.
Eigen::Vector3d barycentric(const Mesh& mesh, int triangle, const Eigen::Vector2d& x) {
  const auto& tri = mesh.cells[triangle];
  const Eigen::Vector2d a = mesh.nodes[tri[0]], b = mesh.nodes[tri[1]], c = mesh.nodes[tri[2]];
  const Eigen::Vector2d e = b - a, f = c - a, r = x - a;
  const double det = e.x() * f.y() - e.y() * f.x(); // > 0: a checked mesh is counter-clockwise
  const double s = (r.x() * f.y() - r.y() * f.x()) / det, t = (e.x() * r.y() - e.y() * r.x()) / det;
  return {1 - s - t, s, t};
}

/// The coarse triangles binned on a uniform grid by their bounding boxes, about one triangle
/// per bin.
class TriangleBins {
public:
  explicit TriangleBins(const Mesh& mesh) : mesh_(mesh) {
    lo_ = hi_ = mesh.nodes.front();
    for (const Point& x : mesh.nodes) {
      lo_ = lo_.cwiseMin(x);
      hi_ = hi_.cwiseMax(x);
    }
    const Eigen::Vector2d size = (hi_ - lo_).cwiseMax(1e-300);
    const double bins = std::max(1, mesh.num_cells());
    cell_ = std::sqrt(size.x() * size.y() / bins);
    if (!(cell_ > 0)) cell_ = std::max(size.x(), size.y());
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    bins_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int t = 0; t < mesh.num_cells(); ++t) {
      Eigen::Vector2d a = mesh.nodes[mesh.cells[t][0]], b = a;
      for (int v : mesh.cells[t]) {
        a = a.cwiseMin(mesh.nodes[v]);
        b = b.cwiseMax(mesh.nodes[v]);
      }
      const auto [i0, j0] = cell_of(a);
      const auto [i1, j1] = cell_of(b);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
          bins_[static_cast<std::size_t>(j) * nx_ + i].push_back(t);
    }
  }

  /// The triangle holding x (its least barycentric coordinate >= -1e-12), or else the one
  /// whose least coordinate is the largest among the bins around x, searched ring by ring.
  int locate(const Eigen::Vector2d& x, Eigen::Vector3d& weights) const {
    const auto [ci, cj] = cell_of(x);
    int best = -1, found_at = 0;
    double best_min = -std::numeric_limits<double>::infinity();
    for (int ring = 0; ring <= std::max(nx_, ny_); ++ring) {
      for (int j = cj - ring; j <= cj + ring; ++j)
        for (int i = ci - ring; i <= ci + ring; ++i) {
          if (std::max(std::abs(i - ci), std::abs(j - cj)) != ring) continue;
          if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
          for (int t : bins_[static_cast<std::size_t>(j) * nx_ + i]) {
            const Eigen::Vector3d w = barycentric(mesh_, t, x);
            if (w.minCoeff() > best_min) {
              if (best < 0) found_at = ring;
              best_min = w.minCoeff();
              best = t;
              weights = w;
            }
          }
        }
      // Inside a triangle, or a candidate found and one ring beyond it searched.
      if (best_min >= -1e-12 || (best >= 0 && ring > found_at)) break;
    }
    return best;
  }

private:
  const Mesh& mesh_;
  Eigen::Vector2d lo_, hi_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> bins_;

  std::array<int, 2> cell_of(const Eigen::Vector2d& x) const {
    const auto clamp = [](double v, int n) {
      return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1);
    };
    return {clamp((x.x() - lo_.x()) / cell_, nx_), clamp((x.y() - lo_.y()) / cell_, ny_)};
  }
};

} // namespace

Eigen::VectorXd prolongate(const Mesh& coarse, const Eigen::VectorXd& u, const Mesh& fine) {
  SIG_VERIFY(u.size() == 2 * coarse.num_nodes(),
             "prolongate: " << u.size() << " values for " << coarse.num_nodes() << " nodes");
  SIG_VERIFY(coarse.num_cells() > 0, "prolongate: the coarse mesh has no triangle");
  const TriangleBins bins(coarse);
  Eigen::VectorXd p(2 * fine.num_nodes());
  for (int i = 0; i < fine.num_nodes(); ++i) {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    const int t = bins.locate(fine.nodes[i], w);
    SIG_VERIFY(t >= 0, "prolongate: no coarse triangle near node " << i + 1);
    Eigen::Vector2d value = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k)
      value += w[k] * u.segment<2>(2 * coarse.cells[t][k]);
    p.segment<2>(2 * i) = value;
  }
  return p;
}

StrainError strain_error(const Mesh& reference, const Eigen::VectorXd& u_ref, const Mesh& coarse,
                         const Eigen::VectorXd& u_h, const std::optional<Window>& window) {
  SIG_VERIFY(u_ref.size() == 2 * reference.num_nodes(),
             "strain_error: " << u_ref.size() << " reference values for " << reference.num_nodes()
                              << " nodes");
  // The reference triangles whose centroid lies in the window, or all of them.
  const auto counts = [&](int t) {
    const auto& v = reference.cells[t];
    return !window ||
           window->contains(
               (reference.nodes[v[0]] + reference.nodes[v[1]] + reference.nodes[v[2]]) / 3);
  };
  if (window) {
    int inside = 0;
    for (int t = 0; t < reference.num_cells(); ++t)
      inside += counts(t);
    SIG_VERIFY(inside > 0, "strain_error: the window ["
                               << window->x0 << ", " << window->x1 << "] x [" << window->y0 << ", "
                               << window->y1 << "] holds no triangle of the mesh");
  }
  const auto norm = [&](const Eigen::VectorXd& u) { return strain_norm(reference, u, counts); };
  StrainError e;
  e.error = norm(u_ref - prolongate(coarse, u_h, reference));
  e.reference_norm = norm(u_ref);
  return e;
}

} // namespace sig
