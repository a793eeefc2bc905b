// ring and rectangle: structured meshes built node by node.
#include "core/error.hpp"
#include "mesh/generators.hpp"

#include <cmath>
#include <numbers>

namespace sig {
namespace {

/// A multiple of the binary grid step q = 2^(e - 52) where 2^e > `magnitude`: sums and
/// differences of such numbers below 2^e are exact, which makes cx + dx and cx - dx exact
/// mirror images.
double on_grid(double value, double magnitude) {
  const double q = std::ldexp(1.0, std::ilogb(magnitude) + 1 - 52);
  return std::nearbyint(value / q) * q;
}

} // namespace

int default_ring_layers(int N) {
  return std::max(2, 3 * N / 64 + 1);
}

Mesh ring(const Eigen::Vector2d& center, double r_in, double r_out, int N,
          const RingOptions& options) {
  const int layers = options.layers > 0 ? options.layers : default_ring_layers(N);
  SIG_VERIFY(0 < r_in && r_in < r_out && std::isfinite(r_out),
             "ring: radii must satisfy 0 < r_in < r_out (r_in = " << r_in << ", r_out = " << r_out
                                                                  << ")");
  SIG_VERIFY(N >= 4 && N % 2 == 0, "ring: N = " << N << " must be even and >= 4");
  SIG_VERIFY(layers >= 2, "ring: layers = " << layers << " must be >= 2");
  const double magnitude = std::abs(center.x()) + r_out;
  const double cx = on_grid(center.x(), magnitude), cy = center.y();
  const double gamma1_above = options.gamma1_above.value_or(cy + 0.99 * r_out);
  const double gamma3_below = options.gamma3_below.value_or(cy + r_out * std::sqrt(2.0) / 2);
  const double tolerance = 1e-9 * r_out; // nodes exactly on a threshold count as on it

  // Node (k, j) = angle -90 + 360 k / N degrees, radius r_j; index j N + k. The right half
  // k = 0..N/2 is computed and node N - k is its mirror: same x2, x1 - cx negated.
  Mesh mesh;
  mesh.nodes.resize(static_cast<std::size_t>(N) * layers);
  for (int j = 0; j < layers; ++j) {
    const double r = r_in + (r_out - r_in) * j / (layers - 1);
    for (int k = 0; k <= N / 2; ++k) {
      const double angle = -std::numbers::pi / 2 + 2 * std::numbers::pi * k / N;
      const double dx = (k == 0 || k == N / 2) ? 0.0 : on_grid(r * std::cos(angle), magnitude);
      const double y = k == 0 ? cy - r : k == N / 2 ? cy + r : cy + r * std::sin(angle);
      mesh.nodes[j * N + k] = {cx + dx, y};
      mesh.nodes[j * N + (N - k) % N] = {cx - dx, y};
    }
  }
  // Each cell (k..k+1, j..j+1) is cut along a diagonal mirrored about x1 = cx: (k, j)-(k+1, j+1)
  // on the right half, (k+1, j)-(k, j+1) on the left.
  auto node = [N](int k, int j) { return j * N + k % N; };
  for (int j = 0; j + 1 < layers; ++j) {
    for (int k = 0; k < N; ++k) {
      const int a = node(k, j), b = node(k + 1, j), c = node(k + 1, j + 1), d = node(k, j + 1);
      if (k < N / 2) { // (angle, radius) is a clockwise frame: list the nodes backwards
        mesh.cells.push_back({a, c, b});
        mesh.cells.push_back({a, d, c});
      } else {
        mesh.cells.push_back({a, d, b});
        mesh.cells.push_back({b, d, c});
      }
    }
  }
  mesh.subdomain.assign(mesh.cells.size(), 1);

  // References: the outer circle runs counter-clockwise, the inner one clockwise (domain left).
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  const int outer = layers - 1;
  for (int k = 0; k < N; ++k) {
    const int a = node(k, outer), b = node(k + 1, outer);
    const bool low = mesh.nodes[a].y() <= gamma3_below + tolerance &&
                     mesh.nodes[b].y() <= gamma3_below + tolerance;
    mesh.facets.push_back({{a, b}, low ? 3 : 2});
    if (mesh.nodes[a].y() >= gamma1_above - tolerance) mesh.vertex_ref[a] = 1;
  }
  for (int k = 0; k < N; ++k)
    mesh.facets.push_back({{node(k + 1, 0), node(k, 0)}, 4});
  check_mesh(mesh, "ring");
  return mesh;
}

Mesh rectangle(double lx, double ly, int nx, int ny, std::array<int, 4> refs, CellPattern pattern) {
  SIG_VERIFY(lx > 0 && ly > 0 && std::isfinite(lx) && std::isfinite(ly),
             "rectangle: sides " << lx << " x " << ly << " must be > 0");
  SIG_VERIFY(nx >= 1 && ny >= 1, "rectangle: " << nx << " x " << ny << " cells");
  for (int r : refs)
    SIG_VERIFY(r >= 1, "rectangle: reference " << r << " must be >= 1");
  auto node = [nx](int i, int j) { return j * (nx + 1) + i; };
  Mesh mesh;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i)
      mesh.nodes.emplace_back(lx * i / nx, ly * j / ny);
  }
  if (pattern == CellPattern::union_jack)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        mesh.nodes.emplace_back(lx * (i + 0.5) / nx, ly * (j + 0.5) / ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      if (pattern == CellPattern::union_jack) {
        const int e = (nx + 1) * (ny + 1) + j * nx + i; // the centre
        mesh.cells.push_back({a, b, e});
        mesh.cells.push_back({b, c, e});
        mesh.cells.push_back({c, d, e});
        mesh.cells.push_back({d, a, e});
      } else if ((i + j) % 2 == 0) {
        mesh.cells.push_back({a, b, c});
        mesh.cells.push_back({a, c, d});
      } else {
        mesh.cells.push_back({a, b, d});
        mesh.cells.push_back({b, c, d});
      }
    }
  }
  mesh.subdomain.assign(mesh.cells.size(), 1);
  const auto [bottom, right, top, left] = refs;
  for (int i = 0; i < nx; ++i)
    mesh.facets.push_back({{node(i, 0), node(i + 1, 0)}, bottom});
  for (int j = 0; j < ny; ++j)
    mesh.facets.push_back({{node(nx, j), node(nx, j + 1)}, right});
  for (int i = nx; i > 0; --i)
    mesh.facets.push_back({{node(i, ny), node(i - 1, ny)}, top});
  for (int j = ny; j > 0; --j)
    mesh.facets.push_back({{node(0, j), node(0, j - 1)}, left});
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  mesh.vertex_ref[node(0, 0)] = mesh.vertex_ref[node(nx, 0)] = bottom;
  mesh.vertex_ref[node(0, ny)] = mesh.vertex_ref[node(nx, ny)] = top;
  check_mesh(mesh, "rectangle");
  return mesh;
}

Mesh square(double l, int n, std::array<int, 4> refs) {
  return rectangle(l, l, n, n, refs);
}

} // namespace sig
