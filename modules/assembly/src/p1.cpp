#include "assembly/p1.hpp"

#include "assembly/p1_simplex.hpp"

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace sig {

template <int d> SimplexVertices<d> simplex_vertices(const Mesh& mesh, int c) {
  SIG_ASSERT(mesh.dim == d, "a mesh of dimension " << mesh.dim << " read as " << d << "D");
  SimplexVertices<d> x;
  for (int i = 0; i <= d; ++i)
    x.col(i) = mesh.nodes[mesh.cells[c][i]];
  return x;
}
template SimplexVertices<2> simplex_vertices<2>(const Mesh&, int);
template SimplexVertices<3> simplex_vertices<3>(const Mesh&, int);

// The 2D kernels are the simplex routine at d = 2 (p1_simplex.hpp).

Matrix23 triangle_vertices(const Mesh& mesh, int t) {
  return simplex_vertices<2>(mesh, t);
}

double p1_area(const Matrix23& x) {
  return p1_measure<2>(x);
}

Matrix23 p1_gradients(const Matrix23& x) {
  SIG_ASSERT(p1_area(x) != 0.0, "degenerate triangle");
  return p1_simplex_gradients<2>(x);
}

Matrix36 p1_strain_matrix(const Matrix23& gradients) {
  return p1_simplex_strain_matrix<2>(gradients);
}

Matrix6d p1_stiffness(const Matrix23& x, const Eigen::Matrix3d& D, double thickness) {
  return p1_simplex_stiffness<2>(x, D, thickness);
}

Matrix6d p1_consistent_mass(double area, double density, double thickness) {
  return p1_simplex_consistent_mass<2>(area, density, thickness);
}

Vector6d p1_lumped_mass(double area, double density, double thickness) {
  return p1_simplex_lumped_mass<2>(area, density, thickness);
}

Vector6d p1_body_load(double area, const Eigen::Vector2d& force, double thickness) {
  return p1_simplex_body_load<2>(area, force, thickness);
}

Eigen::Vector4d p1_edge_load(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             const Eigen::Vector2d& traction, double thickness) {
  const Eigen::Vector2d half = traction * (0.5 * thickness * (b - a).norm());
  Eigen::Vector4d f;
  f << half, half;
  return f;
}

} // namespace sig
