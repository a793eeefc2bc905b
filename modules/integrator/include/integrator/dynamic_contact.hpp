#pragma once
// The contact boundary of a dynamic case, on the free dofs, and the condensation of the step
// operator onto its normal displacements.
//
// With the end-of-step nodal contact forces lambda (>= 0, pushing node i along the obstacle
// normal n_i; force vector -B^T lambda, B the normal operator (B u)_i = u_n,i = -n_i . u_i), the
// step of TimeScheme::advance, multiplied by 2 as it is written there, becomes
//     S d = 2 f_bar - 2 K u_n + (4 / k) M v_n - 2 B^T lambda,   S = K + (4 / k^2) M,
// so d = d_free - 2 Z lambda with Z = S^{-1} B^T, and the normal displacements at t_{n+1},
// x = B (u_n + d), obey
//     x = x_free - 2 C lambda,  C = B Z,   i.e.   A (x - x_free) + lambda = 0,  A = (2 C)^{-1}:
// a small problem on the p contact nodes, whatever the contact law. S is factorized once (by the
// scheme), Z takes p solves once, and a step costs one sparse solve plus dense p-sized work.
// The work of the contact forces over the step is -lambda . (x_{n+1} - x_n), and the midpoint
// rule's discrete energy obeys E_{n+1} - E_n = f_bar . (u_{n+1} - u_n) - lambda . (x_{n+1} - x_n).
#include "solver/contact_newton.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

struct ContactElements;
struct Mesh;
struct ReducedSystem;
class TimeScheme;

struct ContactBoundary {
  std::vector<int> nodes;        ///< 0-based mesh nodes, in CONT element order
  Eigen::SparseMatrix<double> B; ///< p x free dofs: (B u)_i = u_n,i
  /// d_i = distance of node i to the obstacle in the reference configuration (the CONT gap):
  /// the penetration q_n = u_n - d and every law are measured from it.
  Eigen::VectorXd geometric_gap;
  /// The CONT laws (their wall depth g) and weights (tributary length x thickness: pressure =
  /// force / weight).
  ContactSetting setting;

  int size() const { return static_cast<int>(nodes.size()); }
  /// [u_n - d]_+ per node for the normal displacements x.
  Eigen::VectorXd penetration(const Eigen::VectorXd& x) const;
};

/// The boundary on the free dofs of `reduced`, B, gaps, laws and weights as the CONT file has
/// them; sig::Error if a contact node has a Dirichlet dof or is not a node of the mesh.
ContactBoundary contact_boundary(const ContactElements& elements, const Mesh& mesh,
                                 const ReducedSystem& reduced);

/// Z and A of the header comment, for the step operator of `scheme`.
struct CondensedContact {
  Eigen::MatrixXd Z; ///< S^{-1} B^T, free dofs x p
  Eigen::MatrixXd A; ///< (2 B S^{-1} B^T)^{-1}, p x p, symmetric positive definite
};
/// p solves with the scheme's factor; sig::Error if B S^{-1} B^T is not positive definite (two
/// elements on one node).
CondensedContact condense_contact(const TimeScheme& scheme, const ContactBoundary& boundary);

} // namespace sig
