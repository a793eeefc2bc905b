#pragma once
// The P1 simplex of elasticity in R^d, d = 2 (triangle) or 3 (tetrahedron): one routine for both
// dimensions, templated on d. Local dofs are interleaved as in the global numbering: local dof
// d i + c is component c of vertex i; a cell's vertices are the columns of a d x (d + 1) matrix.
// Strains and stresses are Voigt vectors with the engineering shear: (e11, e22, 2 e12) in 2D,
// (e11, e22, e33, 2 e23, 2 e13, 2 e12) in 3D. The 2D kernels of p1.hpp are this routine at d = 2.
#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <type_traits>
#include <utility>

namespace sig {

struct Mesh;

/// Number of Voigt components of a symmetric tensor of R^d: 3 in 2D, 6 in 3D.
constexpr int voigt_size(int d) {
  return d * (d + 1) / 2;
}

template <int d> using SimplexVertices = Eigen::Matrix<double, d, d + 1>;
template <int d> using SimplexStrainMatrix = Eigen::Matrix<double, voigt_size(d), d*(d + 1)>;
template <int d> using SimplexMatrix = Eigen::Matrix<double, d*(d + 1), d*(d + 1)>;
template <int d> using VoigtMatrix = Eigen::Matrix<double, voigt_size(d), voigt_size(d)>;

/// The (row, column) pairs of the shear components in Voigt order: (1, 2) in 2D; (2, 3), (1, 3),
/// (1, 2) in 3D (0-based here).
template <int d> constexpr std::array<std::pair<int, int>, voigt_size(d) - d> voigt_shears() {
  if constexpr (d == 2)
    return {{{0, 1}}};
  else
    return {{{1, 2}, {0, 2}, {0, 1}}};
}

/// f(std::integral_constant<int, d>{}) for the dimension d = 2 or 3 known at run time (a mesh's):
/// how a routine templated on d is entered from code that holds the mesh, e.g.
/// with_dimension(mesh.dim, [&]<int d>(std::integral_constant<int, d>) { return f<d>(mesh); }).
template <typename F> decltype(auto) with_dimension(int dim, F&& f) {
  if (dim == 3) return f(std::integral_constant<int, 3>{});
  return f(std::integral_constant<int, 2>{});
}

/// Vertex coordinates of cell c of a mesh of dimension d, one column per vertex.
template <int d> SimplexVertices<d> simplex_vertices(const Mesh& mesh, int c);

/// Signed measure: the area of a triangle (positive counter-clockwise), the volume of a
/// tetrahedron (positive when right-handed).
template <int d> double p1_measure(const SimplexVertices<d>& x) {
  if constexpr (d == 2) {
    const Eigen::Vector2d e1 = x.col(1) - x.col(0);
    const Eigen::Vector2d e2 = x.col(2) - x.col(0);
    return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  } else {
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j)
      J.col(j) = x.col(j + 1) - x.col(0);
    return J.determinant() / 6.0;
  }
}

/// Gradients of the d + 1 barycentric coordinates, one column per vertex: constant on the cell;
/// their columns sum to zero. In 2D the closed form (the rotated opposite side over twice the
/// area, the 2D results of every scene are made with it); in 3D the rows of the inverse of the
/// edge matrix J = [x1 - x0, x2 - x0, x3 - x0] (grad lambda_j = J^-T e_j, lambda_0 the rest).
template <int d> SimplexVertices<d> p1_simplex_gradients(const SimplexVertices<d>& x) {
  SimplexVertices<d> g;
  if constexpr (d == 2) {
    const double double_area = 2.0 * p1_measure<2>(x);
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector2d& p = x.col((i + 1) % 3);
      const Eigen::Vector2d& q = x.col((i + 2) % 3);
      g.col(i) = Eigen::Vector2d(p.y() - q.y(), q.x() - p.x()) / double_area;
    }
  } else {
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j)
      J.col(j) = x.col(j + 1) - x.col(0);
    const Eigen::Matrix3d inverse_transpose = J.inverse().transpose();
    g.template rightCols<3>() = inverse_transpose;
    g.col(0) = -inverse_transpose.rowwise().sum();
  }
  return g;
}

/// B such that eps = B u_e (Voigt, engineering shear) for the local displacement u_e.
template <int d> SimplexStrainMatrix<d> p1_simplex_strain_matrix(const SimplexVertices<d>& g) {
  SimplexStrainMatrix<d> b = SimplexStrainMatrix<d>::Zero();
  constexpr auto shears = voigt_shears<d>();
  for (int i = 0; i <= d; ++i) {
    for (int k = 0; k < d; ++k)
      b(k, d * i + k) = g(k, i);
    for (int s = 0; s < voigt_size(d) - d; ++s) {
      const auto [p, q] = shears[s];
      b(d + s, d * i + p) = g(q, i);
      b(d + s, d * i + q) = g(p, i);
    }
  }
  return b;
}

/// K_e = thickness * measure * B^T D B: symmetric, positive semi-definite, its kernel the rigid
/// motions (3 in 2D, 6 in 3D). `thickness` is the plate's in 2D and 1 in 3D.
template <int d>
SimplexMatrix<d> p1_simplex_stiffness(const SimplexVertices<d>& x, const VoigtMatrix<d>& D,
                                      double thickness) {
  const SimplexStrainMatrix<d> b = p1_simplex_strain_matrix<d>(p1_simplex_gradients<d>(x));
  return (thickness * p1_measure<d>(x)) * (b.transpose() * D * b);
}

template <int d> using SimplexVector = Eigen::Matrix<double, d*(d + 1), 1>;

/// Consistent mass rho t int(phi_i phi_j) = rho t measure (1 + delta_ij) / ((d + 1)(d + 2)) per
/// component (/ 12 for a triangle, / 20 for a tetrahedron).
template <int d>
SimplexMatrix<d> p1_simplex_consistent_mass(double measure, double density, double thickness) {
  const double scale = density * thickness * measure / ((d + 1) * (d + 2));
  SimplexMatrix<d> m = SimplexMatrix<d>::Zero();
  for (int i = 0; i <= d; ++i)
    for (int j = 0; j <= d; ++j)
      for (int c = 0; c < d; ++c)
        m(d * i + c, d * j + c) = scale * (i == j ? 2.0 : 1.0);
  return m;
}

/// Lumped mass: the row sums of the consistent mass, rho t measure / (d + 1) per dof.
template <int d>
SimplexVector<d> p1_simplex_lumped_mass(double measure, double density, double thickness) {
  return SimplexVector<d>::Constant(density * thickness * measure / (d + 1.0));
}

/// Nodal forces of a constant body force (per unit volume): force t measure / (d + 1) at each
/// vertex.
template <int d>
SimplexVector<d> p1_simplex_body_load(double measure, const Eigen::Matrix<double, d, 1>& force,
                                      double thickness) {
  SimplexVector<d> f;
  for (int i = 0; i <= d; ++i)
    f.template segment<d>(d * i) = force * (thickness * measure / (d + 1.0));
  return f;
}

} // namespace sig
