#pragma once
// Small meshes built by hand for the assembly tests, independent of the mesh module's
// generators: a square with perturbed interior nodes and a structured quarter ring.
#include "mesh/mesh.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace sig::test {

/// The square [0, L]^2 cut into nx x ny cells, each split into two triangles along alternating
/// diagonals; interior nodes moved by up to `perturbation` times the cell size. Edge references:
/// 1 bottom, 2 right, 3 top, 4 left (counter-clockwise, domain on the left); vertex (0, 0) also
/// carries reference 5. Triangles with x < L/2 at their centroid are in sub-domain 1, the others
/// in sub-domain `right_subdomain`.
inline Mesh square_mesh(int nx, int ny, double L = 1.0, double perturbation = 0.0,
                        int right_subdomain = 1, unsigned seed = 7) {
  Mesh mesh;
  const double hx = L / nx, hy = L / ny;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-perturbation, perturbation);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      Eigen::Vector2d x(i * hx, j * hy);
      if (i > 0 && i < nx && j > 0 && j < ny) {
        x.x() += shift(rng) * hx;
        x.y() += shift(rng) * hy;
      }
      mesh.nodes.push_back(x);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        mesh.cells.push_back({a, b, c});
        mesh.cells.push_back({a, c, d});
      } else {
        mesh.cells.push_back({a, b, d});
        mesh.cells.push_back({b, c, d});
      }
    }
  for (const auto& t : mesh.cells) {
    const double xc = (mesh.nodes[t[0]].x() + mesh.nodes[t[1]].x() + mesh.nodes[t[2]].x()) / 3;
    mesh.subdomain.push_back(xc < L / 2 ? 1 : right_subdomain);
  }
  for (int i = 0; i < nx; ++i)
    mesh.facets.push_back({{id(i, 0), id(i + 1, 0)}, 1});
  for (int j = 0; j < ny; ++j)
    mesh.facets.push_back({{id(nx, j), id(nx, j + 1)}, 2});
  for (int i = nx; i > 0; --i)
    mesh.facets.push_back({{id(i, ny), id(i - 1, ny)}, 3});
  for (int j = ny; j > 0; --j)
    mesh.facets.push_back({{id(0, j), id(0, j - 1)}, 4});
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  mesh.vertex_ref[id(0, 0)] = 5;
  return mesh;
}

/// The quarter ring r in [r_in, r_out], theta in [0, pi/2] on a polar grid of nr x nt cells.
/// Edge references: 1 inner arc, 2 outer arc, 3 the side x2 = 0, 4 the side x1 = 0.
inline Mesh quarter_ring_mesh(int nr, int nt, double r_in, double r_out) {
  Mesh mesh;
  auto id = [&](int i, int j) { return j * (nr + 1) + i; }; // i radial, j angular
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= nr; ++i) {
      const double r = r_in + (r_out - r_in) * i / nr;
      const double theta = 0.5 * std::numbers::pi * j / nt;
      // Exact zeros on the symmetry axes, so the sides lie on x2 = 0 and x1 = 0.
      mesh.nodes.emplace_back(j == nt ? 0.0 : r * std::cos(theta),
                              j == 0 ? 0.0 : r * std::sin(theta));
    }
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      mesh.cells.push_back({a, b, c});
      mesh.cells.push_back({a, c, d});
    }
  mesh.subdomain.assign(mesh.cells.size(), 1);
  for (int j = nt; j > 0; --j)
    mesh.facets.push_back({{id(0, j), id(0, j - 1)}, 1});
  for (int j = 0; j < nt; ++j)
    mesh.facets.push_back({{id(nr, j), id(nr, j + 1)}, 2});
  for (int i = 0; i < nr; ++i)
    mesh.facets.push_back({{id(i, 0), id(i + 1, 0)}, 3});
  for (int i = nr; i > 0; --i)
    mesh.facets.push_back({{id(i, nt), id(i - 1, nt)}, 4});
  mesh.vertex_ref.assign(mesh.nodes.size(), 0);
  return mesh;
}

} // namespace sig::test
