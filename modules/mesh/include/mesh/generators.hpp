#pragma once
// Meshes of the thesis geometries (SCENES.md), each returned checked (check_mesh), with the
// references the scenes use. half_disc and disc call gmsh on meshes/half_disc.geo and
// meshes/disc.geo (compiled into the library; the gmsh binary is `gmsh` or $SIG_GMSH); ring
// and rectangle are structured and built here.
#include "mesh/mesh.hpp"

#include <array>
#include <optional>

namespace sig {

/// Hertz body { x1^2 + (x2-R)^2 <= R^2, x2 <= R } (scene 7a). Exactly N uniform segments on the
/// lower half circle (ref 3 = Gamma3, N + 1 nodes, one of them (0, 0)), the top diameter edges
/// ref 2, the top centre node (0, R) vertex_ref 1; N even. Mesh size h = pi R / N at the arc,
/// h + grading * d at distance d from it, capped at R / 4.
Mesh half_disc(double R, int N, double grading = 0);

/// Disc of centre `center` and radius R in four quarter arcs of N/4 segments (N multiple of
/// 4): left quarter (x1 <= cx - R/sqrt2) ref 1, top ref 2, bottom ref 3 (contact side), right
/// ref 4. Size law as half_disc with h = 2 pi R / N, d measured from the bottom quarter.
/// `graded_arcs`: only the bottom quarter has N/4 uniform segments, the size law sets the
/// others' (a mesh fine only near the contact side, scene 4).
Mesh disc(const Eigen::Vector2d& center, double R, int N, double grading = 0,
          bool graded_arcs = false);

/// Box [0, lx] x [0, ly] x [0, lz] of tetrahedra of size h (meshes/box.geo): faces ref 1 the
/// base x3 = 0, 2 the top x3 = lz, 3 the four sides; one sub-domain.
Mesh box(double lx, double ly, double lz, double h);

/// Hertz half ball { |x - (0, 0, R)| <= R, x3 <= R } of tetrahedra (meshes/half_ball.geo): the
/// half sphere ref 3 (Gamma3), the flat top ref 2, the top centre (0, 0, R) vertex_ref 1. Its
/// lowest point, the pole, is the origin and a node. Mesh size h + grading * d at distance d
/// from the pole, capped at `cap` (0: R / 4; never below h); grading = 0: uniform, size h.
Mesh half_ball(double R, double h, double grading = 0, double cap = 0);

/// Ball of centre `centre` (3 coordinates) and radius R of tetrahedra of size h
/// (meshes/ball.geo): the sphere ref 3 (Gamma3).
Mesh ball(const Point& centre, double R, double h);

/// Wheel-like cylinder of radius R, axis along x2 from x2 = 0 to L through (0, *, R), resting
/// on x3 = 0, of tetrahedra of size h (meshes/cylinder.geo): the curved side ref 3 (the tread),
/// the two flat ends ref 2.
Mesh cylinder(double R, double L, double h);

struct RingOptions {
  int layers = 0;                     ///< nodes through the thickness; 0 = default_ring_layers(N)
  std::optional<double> gamma1_above; ///< default cy + 0.99 r_out
  std::optional<double> gamma3_below; ///< default cy + r_out sqrt(2) / 2
};
/// 3N/64 + 1 nodes through the thickness, as in the thesis (at least 2).
int default_ring_layers(int N);

/// Structured ring r_in <= |x - center| <= r_out (scenes 7b, 8b): N nodes around (N even), one
/// of them at the bottom (angle -90 degrees), `layers` circles. Exactly mirror-symmetric about
/// x1 = cx: each node has a mirror with bit-identical |x1 - cx| and x2 (the centre and the
/// offsets are rounded to a common binary grid so that cx +- dx are exact). Refs: outer edges
/// with both ends at x2 <= gamma3_below ref 3 (Gamma3), other outer edges ref 2, inner edges ref
/// 4; outer nodes with x2 >= gamma1_above vertex_ref 1 (Gamma1 = AB).
Mesh ring(const Eigen::Vector2d& center, double r_in, double r_out, int N,
          const RingOptions& options = {});

/// How a rectangle's cells are cut: `alternating`, two triangles along a diagonal that alternates
/// from cell to cell; `union_jack`, four triangles around a node at the cell's centre (the
/// thesis's scene 5 mesh, ALGORITHMS.md 0.2: 64 x 12 cells, 3072 triangles). A union-jack mesh
/// refined by halving nx and ny is nested in the coarse one (each coarse edge is a union of fine
/// edges), so coarse P1 fields prolongate onto it exactly.
enum class CellPattern { alternating, union_jack };

/// Structured [0, lx] x [0, ly], nx x ny cells cut by `pattern`. refs = {bottom, right, top,
/// left}; the corners get the vertex_ref of the bottom or top side. Nodes: the (nx + 1)(ny + 1)
/// corners row by row from the bottom, then (union jack) the nx ny centres row by row.
Mesh rectangle(double lx, double ly, int nx, int ny, std::array<int, 4> refs = {3, 4, 2, 1},
               CellPattern pattern = CellPattern::alternating);
/// rectangle(l, l, n, n, refs).
Mesh square(double l, int n, std::array<int, 4> refs = {3, 4, 2, 1});

} // namespace sig
