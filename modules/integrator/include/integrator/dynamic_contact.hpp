#pragma once
// The contact boundary of a dynamic case, on the free dofs, and the condensation of the step
// operator onto its nodes' normal displacements and, with friction, their slips.
//
// With the end-of-step nodal contact forces lambda = N (>= 0, pushing node i along the obstacle
// normal n_i) and, with friction, T (opposing the slip along t_i = (n2, -n1); in 3D a vector of
// the node's tangent plane, its components along t1_i, t2_i), the force vector is -G^T lambda,
// G the components operator: B, (B u)_i = u_n,i = -n_i . u_i, or B over B_t, (B_t u)_i =
// t_i . u_i with friction (3D: two rows a node, t1_i . u_i and t2_i . u_i). The step of
// TimeScheme::advance, multiplied by 2 as it is written there, becomes
//     S d = 2 f_bar - 2 K u_n + (4 / k) M v_n - 2 G^T lambda,   S = K + (4 / k^2) M,
// so d = d_free - 2 Z lambda with Z = S^{-1} G^T, and the components at t_{n+1},
// x = G (u_n + d), obey
//     x = x_free - 2 C lambda,  C = G Z,   i.e.   A (x - x_free) + lambda = 0,  A = (2 C)^{-1}:
// a small problem on the p contact nodes (p, or d p with friction), whatever the contact law. S is
// factorized once (by the scheme), Z takes p (d p) solves once, and a step costs one sparse solve
// plus dense work of that size. The work of the contact forces over the step is
// -lambda . (x_{n+1} - x_n): -N . (q_{n+1} - q_n) - T . slip, the slip being the increment of the
// tangential displacement over the step, and the midpoint rule's discrete energy obeys
// E_{n+1} - E_n = f_bar . (u_{n+1} - u_n) - lambda . (x_{n+1} - x_n).
#include "solver/contact_newton.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace sig {

class TimeScheme;

struct ContactBoundary {
  std::vector<int> nodes;        ///< 0-based mesh nodes, in CONT element order
  Eigen::SparseMatrix<double> B; ///< p x free dofs: (B u)_i = u_n,i
  /// (d - 1) p x free dofs: the tangential displacements, in 2D (tangential u)_i = t_i . u_i
  /// along t_i = (n2, -n1), in 3D rows 2 i and 2 i + 1 along t1_i and t2_i of the node's contact
  /// frame (contact/contact_law.hpp)
  Eigen::SparseMatrix<double> tangential;
  /// d_i = distance of node i to the obstacle in the reference configuration (the CONT gap):
  /// the penetration q_n = u_n - d and every law are measured from it.
  Eigen::VectorXd geometric_gap;
  /// The CONT laws (their wall depth g) and weights (tributary length x thickness: pressure =
  /// force / weight).
  ContactSetting setting;

  /// The contact nodes left out of the condensation (a candidate zone, SOLVER candidate_gap=),
  /// watched only: their u_n rows (free dofs) and gaps d. They carry no force; a step that
  /// brings one beyond the obstacle surface (watched u - watched_gap > 0) fails, naming it.
  Eigen::SparseMatrix<double> watched;
  Eigen::VectorXd watched_gap;
  std::vector<int> watched_nodes; ///< their 0-based mesh nodes (messages)

  int size() const { return static_cast<int>(nodes.size()); }
  /// [u_n - d]_+ per node for the normal displacements x.
  Eigen::VectorXd penetration(const Eigen::VectorXd& x) const;
};

/// G, Z and A of the header comment, for the step operator of `scheme`.
struct CondensedContact {
  /// The components: B (frictionless), or B over the tangential operator (friction): m = p or
  /// d p rows, the normal displacements first.
  Eigen::SparseMatrix<double> G;
  Eigen::MatrixXd Z; ///< S^{-1} G^T, free dofs x m
  Eigen::MatrixXd A; ///< (2 G S^{-1} G^T)^{-1}, m x m, symmetric positive definite
};
/// m solves with the scheme's factor, the slips among the components when a law of the
/// boundary has friction; sig::Error if G S^{-1} G^T is not positive definite (two elements on
/// one node).
CondensedContact condense_contact(const TimeScheme& scheme, const ContactBoundary& boundary);

} // namespace sig
