#pragma once
// Kernels of the P1 (linear, 3-node) triangle for 2D elasticity. Local dofs are interleaved as
// in the global numbering: local dof 2 i + c is component c of vertex i. A triangle's vertices
// are the columns of a 2x3 matrix. Every kernel is per unit thickness times `thickness`, so a
// plane-strain body has thickness 1 and a plane-stress plate its own.
#include <Eigen/Core>

namespace sig {

struct Mesh;

using Matrix23 = Eigen::Matrix<double, 2, 3>;
using Matrix36 = Eigen::Matrix<double, 3, 6>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Vertex coordinates of triangle t of the mesh, one column per vertex.
Matrix23 triangle_vertices(const Mesh& mesh, int t);

/// Signed area (positive for a counter-clockwise triangle).
double p1_area(const Matrix23& x);

/// Gradients of the three barycentric coordinates, one column per vertex: constant on the
/// triangle; their columns sum to zero.
Matrix23 p1_gradients(const Matrix23& x);

/// B such that eps = (e11, e22, 2 e12) = B u_e for the local displacement u_e.
Matrix36 p1_strain_matrix(const Matrix23& gradients);

/// K_e = thickness * area * B^T D B; symmetric, positive semi-definite of rank 3 (the rigid
/// motions span its kernel).
Matrix6d p1_stiffness(const Matrix23& x, const Eigen::Matrix3d& D, double thickness);

/// Consistent mass rho t int(phi_i phi_j) = rho t area (1 + delta_ij) / 12 per component.
Matrix6d p1_consistent_mass(double area, double density, double thickness);

/// Lumped mass: the row sums of the consistent mass, rho t area / 3 per dof.
Vector6d p1_lumped_mass(double area, double density, double thickness);

/// Nodal forces of a constant body force f (per unit volume): f t area / 3 at each vertex.
Vector6d p1_body_load(double area, const Eigen::Vector2d& force, double thickness);

/// Nodal forces of a constant traction g on the straight edge [a, b] (per unit area of the
/// lateral surface): g t |b - a| / 2 at each end; returned as (a_x, a_y, b_x, b_y).
Eigen::Vector4d p1_edge_load(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             const Eigen::Vector2d& traction, double thickness);

} // namespace sig
