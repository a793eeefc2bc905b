// half_disc and disc: gmsh meshes of the scripts in meshes/, whose arc nodes are then put at
// their exact polar positions (gmsh places them to about 1e-9 R).
#include "core/error.hpp"
#include "gmsh_run.hpp"
#include "mesh/generators.hpp"
#include "mesh/geo_scripts.hpp"

#include <cmath>
#include <numbers>

namespace sig {
namespace {

/// cos and sin, exactly 0 at multiples of pi/2 (so the lowest node of a circle is exactly on
/// the horizontal tangent x2 = cy - R and exactly at x1 = cx).
Eigen::Vector2d unit_direction(double angle) {
  double c = std::cos(angle), s = std::sin(angle);
  if (std::abs(c) < 1e-15) c = 0;
  if (std::abs(s) < 1e-15) s = 0;
  return {c, s};
}

/// Move the nodes of the edges with reference `ref` to center + R (cos, sin)(angle0 + k step),
/// k = 0..segments, checking there are exactly segments + 1 of them at distinct angles.
void snap_arc(Mesh& mesh, int ref, const Eigen::Vector2d& center, double R, double angle0,
              int segments, double step, const char* what) {
  const std::vector<int> nodes = mesh.nodes_with_ref(ref);
  SIG_VERIFY(static_cast<int>(nodes.size()) == segments + 1,
             what << ": gmsh put " << nodes.size() << " nodes on the arc of reference " << ref
                  << ", expected " << segments + 1);
  const long period = std::lround(2 * std::numbers::pi / step);
  std::vector<char> taken(segments + 1, 0);
  for (int i : nodes) {
    const Eigen::Vector2d d = mesh.nodes[i] - center;
    const double angle = std::atan2(d.y(), d.x());
    const long k = ((std::lround((angle - angle0) / step) % period) + period) % period;
    SIG_VERIFY(k <= segments && !taken[k],
               what << ": node " << i + 1 << " is not at a free arc position");
    taken[k] = 1;
    mesh.nodes[i] = center + R * unit_direction(angle0 + k * step);
  }
}

void verify_size_law(const char* what, double R, double grading) {
  SIG_VERIFY(R > 0 && std::isfinite(R), what << ": radius " << R << " must be > 0");
  SIG_VERIFY(grading >= 0 && std::isfinite(grading),
             what << ": grading " << grading << " must be >= 0");
}

} // namespace

Mesh half_disc(double R, int N, double grading) {
  verify_size_law("half_disc", R, grading);
  SIG_VERIFY(N >= 4 && N % 2 == 0, "half_disc: N = " << N << " must be even and >= 4");
  Mesh mesh =
      mesh_with_gmsh("half_disc", geo::half_disc, {{"R", R}, {"N", N}, {"grading", grading}});
  snap_arc(mesh, 3, {0, R}, R, -std::numbers::pi, N, std::numbers::pi / N, "half_disc");
  check_mesh(mesh, "half_disc");
  return mesh;
}

Mesh disc(const Eigen::Vector2d& center, double R, int N, double grading, bool graded_arcs) {
  verify_size_law("disc", R, grading);
  SIG_VERIFY(N >= 4 && N % 4 == 0, "disc: N = " << N << " must be a multiple of 4");
  Mesh mesh = mesh_with_gmsh("disc", geo::disc,
                             {{"cx", center.x()},
                              {"cy", center.y()},
                              {"R", R},
                              {"N", N},
                              {"grading", grading},
                              {"graded_arcs", graded_arcs ? 1 : 0}});
  // Quarter k (right, top, left, bottom) starts at -45 + 90 k degrees; ref 4, 2, 1, 3. Graded
  // quarters have no uniform positions: their nodes go radially onto the circle.
  const double step = 2 * std::numbers::pi / N;
  const std::array<int, 4> refs = {4, 2, 1, 3};
  for (int q = 0; q < 4; ++q) {
    if (graded_arcs && refs[q] != 3) {
      for (int i : mesh.nodes_with_ref(refs[q]))
        mesh.nodes[i] = center + R * (mesh.nodes[i] - center).normalized();
      continue;
    }
    snap_arc(mesh, refs[q], center, R, (2 * q - 1) * std::numbers::pi / 4, N / 4, step, "disc");
  }
  check_mesh(mesh, "disc");
  return mesh;
}

} // namespace sig
