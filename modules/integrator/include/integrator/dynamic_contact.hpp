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
// so the components' increment w = G d obeys, with S_c the Schur complement of S (turned into
// the nodes' contact frames) onto the components and g = the condensed right side,
//     S_c w = g - 2 lambda,  i.e.  A (w - w_free) + lambda = 0,  A = S_c / 2,  w_free = S_c^-1 g
// (C = G S^{-1} G^T = S_c^{-1}): a small problem on the p contact nodes (p, or d p with friction),
// whatever the contact law. S is factorized once with the components as its Schur complement
// (solver/contact_condensation.hpp: the machinery of the marches in velocity; under mpirun MUMPS
// over the ranks' rows, the complement on rank 0 and sent to every rank), S_c densely once more,
// and a step is one sparse solve split around the contact problem: g (the forward half), then,
// the forces found, w exactly from them and d with G d = w (the backward half). The work of the
// contact forces over the step is
// -lambda . (x_{n+1} - x_n): -N . (q_{n+1} - q_n) - T . slip, the slip being the increment of the
// tangential displacement over the step, and the midpoint rule's discrete energy obeys
// E_{n+1} - E_n = f_bar . (u_{n+1} - u_n) - lambda . (x_{n+1} - x_n).
#include "contact/contact_law.hpp"
#include "solver/contact_newton.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace sig {

class ContactCondensation;
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
  /// Per node: the first of its d consecutive free dofs and its contact frame (tangents, then
  /// -n: the columns of B's and the tangential operator's rows), by which the step operator is
  /// condensed.
  std::vector<int> first_dof;
  std::vector<ContactFrame> frame;

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

/// G, A and S_c of the header comment for the step operator of `scheme`, in G's order (the
/// normal displacements first), and the step operator's factorization they come from.
class CondensedContact {
public:
  /// S factorized with the components of `boundary` as its Schur complement (the slips among
  /// them when a law has friction), by the scheme's backend, over the ranks where the scheme
  /// holds rank rows. sig::Error if a node is in two contact elements, or the body with its
  /// contact components held cannot be factorized.
  CondensedContact(const TimeScheme& scheme, const ContactBoundary& boundary);
  ~CondensedContact();
  CondensedContact(CondensedContact&&) noexcept;
  CondensedContact& operator=(CondensedContact&&) noexcept;

  /// The components: B (frictionless), or B over the tangential operator (friction): m = p or
  /// d p rows, the normal displacements first.
  const Eigen::SparseMatrix<double>& G() const { return G_; }
  /// S_c / 2, m x m, symmetric positive definite.
  const Eigen::MatrixXd& A() const { return A_; }
  /// g: the condensed right side b (free dofs, whole), remembered for increment().
  Eigen::VectorXd condense(const Eigen::VectorXd& b);
  /// S_c^{-1} r (r of size m).
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const { return schur_.solve(r); }
  /// The increment d (free dofs) of the last condense()'s right side whose components are w.
  Eigen::VectorXd increment(const Eigen::VectorXd& w);
  /// MUMPS's ordering of S (empty with another backend).
  std::string ordering() const;

private:
  Eigen::SparseMatrix<double> G_;
  std::unique_ptr<ContactCondensation> condensation_;
  std::vector<int> position_; ///< per row of G: its place among the condensation's unknowns
  Eigen::MatrixXd A_;
  Eigen::LLT<Eigen::MatrixXd> schur_; ///< of S_c, in G's order
};

} // namespace sig
