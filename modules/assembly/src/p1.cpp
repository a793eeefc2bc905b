#include "assembly/p1.hpp"

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace sig {

Matrix23 triangle_vertices(const Mesh& mesh, int t) {
  Matrix23 x;
  for (int i = 0; i < 3; ++i)
    x.col(i) = mesh.nodes[mesh.triangles[t][i]];
  return x;
}

double p1_area(const Matrix23& x) {
  const Eigen::Vector2d e1 = x.col(1) - x.col(0);
  const Eigen::Vector2d e2 = x.col(2) - x.col(0);
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

Matrix23 p1_gradients(const Matrix23& x) {
  const double double_area = 2.0 * p1_area(x);
  SIG_ASSERT(double_area != 0.0, "degenerate triangle");
  Matrix23 g;
  // grad lambda_i is the inward normal of the opposite edge divided by twice the area.
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d& p = x.col((i + 1) % 3);
    const Eigen::Vector2d& q = x.col((i + 2) % 3);
    g.col(i) = Eigen::Vector2d(p.y() - q.y(), q.x() - p.x()) / double_area;
  }
  return g;
}

Matrix36 p1_strain_matrix(const Matrix23& gradients) {
  Matrix36 b = Matrix36::Zero();
  for (int i = 0; i < 3; ++i) {
    const double dx = gradients(0, i);
    const double dy = gradients(1, i);
    b(0, 2 * i) = dx;
    b(1, 2 * i + 1) = dy;
    b(2, 2 * i) = dy;
    b(2, 2 * i + 1) = dx;
  }
  return b;
}

Matrix6d p1_stiffness(const Matrix23& x, const Eigen::Matrix3d& D, double thickness) {
  const Matrix36 b = p1_strain_matrix(p1_gradients(x));
  return (thickness * p1_area(x)) * (b.transpose() * D * b);
}

Matrix6d p1_consistent_mass(double area, double density, double thickness) {
  const double scale = density * thickness * area / 12.0;
  Matrix6d m = Matrix6d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 2; ++c)
        m(2 * i + c, 2 * j + c) = scale * (i == j ? 2.0 : 1.0);
  return m;
}

Vector6d p1_lumped_mass(double area, double density, double thickness) {
  return Vector6d::Constant(density * thickness * area / 3.0);
}

Vector6d p1_body_load(double area, const Eigen::Vector2d& force, double thickness) {
  Vector6d f;
  for (int i = 0; i < 3; ++i)
    f.segment<2>(2 * i) = force * (thickness * area / 3.0);
  return f;
}

Eigen::Vector4d p1_edge_load(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             const Eigen::Vector2d& traction, double thickness) {
  const Eigen::Vector2d half = traction * (0.5 * thickness * (b - a).norm());
  Eigen::Vector4d f;
  f << half, half;
  return f;
}

} // namespace sig
