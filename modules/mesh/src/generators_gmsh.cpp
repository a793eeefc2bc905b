// half_disc and disc: gmsh meshes of the scripts in meshes/, whose arc nodes are then put at
// their exact polar positions (gmsh places them to about 1e-9 R). box and half_ball: the 3D
// bodies of issue 26, meshed with tetrahedra by gmsh as they come (no node moved yet).
#include "core/error.hpp"
#include "gmsh_run.hpp"
#include "mesh/generators.hpp"
#include "mesh/geo_scripts.hpp"

#include <algorithm>
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

// The scripts' size laws (h = pi R / N, h + grading d, a cap of R / 4) scale with R, so gmsh
// meshes the shape scaled by a power of two that brings R into [1, 2), and the nodes are scaled
// back: gmsh's tolerances are absolute (1e-8), and at R = 1e20 it fails, at R = 1e29 it runs
// without end, at R = 1e-25 it ignores the size law. A power of two scales every product, quotient
// and square root exactly, so the mesh of a radius near 1 is the one gmsh makes of it (a scale by
// 10 moves a frontal mesher's choices: scene 4's ball gained 24 nodes).
double gmsh_scale(double R) {
  int exponent = 0;
  std::frexp(R, &exponent); // R = m 2^exponent, m in [0.5, 1)
  return std::ldexp(1.0, exponent - 1);
}

void scale_nodes(Mesh& mesh, double scale) {
  for (Point& x : mesh.nodes)
    x *= scale;
}

} // namespace

Mesh half_disc(double R, int N, double grading) {
  verify_size_law("half_disc", R, grading);
  SIG_VERIFY(N >= 4 && N % 2 == 0, "half_disc: N = " << N << " must be even and >= 4");
  const double scale = gmsh_scale(R);
  Mesh mesh = mesh_with_gmsh("half_disc", geo::half_disc,
                             {{"R", R / scale}, {"N", N}, {"grading", grading}});
  scale_nodes(mesh, scale);
  snap_arc(mesh, 3, {0, R}, R, -std::numbers::pi, N, std::numbers::pi / N, "half_disc");
  check_mesh(mesh, "half_disc");
  return mesh;
}

Mesh disc(const Eigen::Vector2d& center, double R, int N, double grading, bool graded_arcs) {
  verify_size_law("disc", R, grading);
  SIG_VERIFY(N >= 4 && N % 4 == 0, "disc: N = " << N << " must be a multiple of 4");
  const double scale = gmsh_scale(R);
  Mesh mesh = mesh_with_gmsh("disc", geo::disc,
                             {{"cx", center.x() / scale},
                              {"cy", center.y() / scale},
                              {"R", R / scale},
                              {"N", N},
                              {"grading", grading},
                              {"graded_arcs", graded_arcs ? 1 : 0}});
  scale_nodes(mesh, scale);
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

Mesh box(double lx, double ly, double lz, double h) {
  for (const double length : {lx, ly, lz, h})
    SIG_VERIFY(length > 0 && std::isfinite(length), "box: length " << length << " must be > 0");
  // gmsh's tolerances are absolute: the box is meshed at the scale of its longest side, as the
  // discs are (gmsh_scale).
  const double scale = gmsh_scale(std::max({lx, ly, lz}));
  Mesh mesh = mesh_with_gmsh(
      "box", geo::box,
      {{"lx", lx / scale}, {"ly", ly / scale}, {"lz", lz / scale}, {"h", h / scale}}, 3);
  scale_nodes(mesh, scale);
  check_mesh(mesh, "box");
  return mesh;
}

Mesh half_ball(double R, double h, double grading, double cap) {
  verify_size_law("half_ball", R, grading);
  SIG_VERIFY(h > 0 && std::isfinite(h), "half_ball: mesh size " << h << " must be > 0");
  SIG_VERIFY(cap >= 0 && std::isfinite(cap), "half_ball: cap " << cap << " must be >= 0");
  const double scale = gmsh_scale(R);
  Mesh mesh = mesh_with_gmsh(
      "half_ball", geo::half_ball,
      {{"R", R / scale}, {"h", h / scale}, {"grading", grading}, {"cap", cap / scale}}, 3);
  scale_nodes(mesh, scale);
  check_mesh(mesh, "half_ball");
  return mesh;
}

Mesh ball(const Point& centre, double R, double h) {
  verify_size_law("ball", R, 0);
  SIG_VERIFY(centre.size() == 3, "ball: the centre has " << centre.size() << " coordinates");
  SIG_VERIFY(h > 0 && std::isfinite(h), "ball: mesh size " << h << " must be > 0");
  const double scale = gmsh_scale(R);
  Mesh mesh = mesh_with_gmsh("ball", geo::ball,
                             {{"cx", centre.x() / scale},
                              {"cy", centre.y() / scale},
                              {"cz", centre.z() / scale},
                              {"R", R / scale},
                              {"h", h / scale}},
                             3);
  scale_nodes(mesh, scale);
  check_mesh(mesh, "ball");
  return mesh;
}

Mesh cylinder(double R, double L, double h) {
  verify_size_law("cylinder", R, 0);
  for (const double length : {L, h})
    SIG_VERIFY(length > 0 && std::isfinite(length),
               "cylinder: length " << length << " must be > 0");
  const double scale = gmsh_scale(std::max(R, L));
  Mesh mesh = mesh_with_gmsh("cylinder", geo::cylinder,
                             {{"R", R / scale}, {"L", L / scale}, {"h", h / scale}}, 3);
  scale_nodes(mesh, scale);
  check_mesh(mesh, "cylinder");
  return mesh;
}

} // namespace sig
