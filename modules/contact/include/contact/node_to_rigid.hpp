#pragma once
// The node-to-rigid contact element of thesis Remark 3.1 as a local kernel: one Gamma3 node
// (displacement u, 2 dofs) plus one Lagrange-multiplier node (lambda, 1 dof). It only knows its
// normal n (of the obstacle), its gap g and its parameter; a generic assembler scatters its local
// residual and tangent with the element's dofs (2 node, 2 node + 1, lagrange dof) (STYLE.md 6).
//
// Local unknowns x = (u_1, u_2, lambda); nu = -n is the body's outward normal, u_n = nu . u.
#include "contact/complementarity.hpp"

#include <Eigen/Core>

namespace sig {

using NodeToRigidVector = Eigen::Matrix<double, 3, 1>;
using NodeToRigidMatrix = Eigen::Matrix<double, 3, 3>;

/// Contribution of one element to the symmetric Alart-Curnier system (3.10), gap included:
/// \f[ F(u, \lambda) = \begin{pmatrix} [\lambda + r(u_n - g)]_+ \, \nu
///     \\ -\tfrac{1}{r}\{\lambda - [\lambda + r(u_n - g)]_+\} \end{pmatrix}, \qquad \nu = -n. \f]
/// The first row adds to A(u) - f; the second row is alart_curnier_normal scaled by -1/r, which
/// makes the tangent symmetric (it is the gradient of the augmented Lagrangian (3.7)).
inline NodeToRigidVector alart_curnier_residual(const NodeToRigidVector& x,
                                                const Eigen::Vector2d& n, double g, double r) {
  const Eigen::Vector2d nu = -n;
  const double un = nu.dot(x.head<2>());
  const double lambda = x(2);
  NodeToRigidVector f;
  f.head<2>() = positive_part(lambda + r * (un - g)) * nu;
  f(2) = -alart_curnier_normal(lambda, un, g, r) / r;
  return f;
}

/// Generalized Jacobian of alart_curnier_residual, \f$ H = d[\,]_+(\lambda + r(u_n - g)) \f$:
/// \f[ L = \begin{pmatrix} r H \nu\nu^T & H \nu \\ H \nu^T & -(1 - H)/r \end{pmatrix}. \f]
inline NodeToRigidMatrix alart_curnier_tangent(const NodeToRigidVector& x, const Eigen::Vector2d& n,
                                               double g, double r) {
  const Eigen::Vector2d nu = -n;
  const double un = nu.dot(x.head<2>());
  const double lambda = x(2);
  const double h = d_positive_part(lambda + r * (un - g));
  const Eigen::Matrix2d nu_nu = nu * nu.transpose(); // exactly symmetric before scaling
  NodeToRigidMatrix t;
  t.topLeftCorner<2, 2>() = (r * h) * nu_nu;
  t.topRightCorner<2, 1>() = h * nu;
  t.bottomLeftCorner<1, 2>() = h * nu.transpose();
  t(2, 2) = -d_alart_curnier_normal_d_lambda(lambda, un, g, r) / r;
  return t;
}

/// Penalty element (Remark 3.2): the displacement rows only, \f$ r [u_n - g]_+ \nu \f$.
inline Eigen::Vector2d penalty_residual(const Eigen::Vector2d& u, const Eigen::Vector2d& n,
                                        double g, double r) {
  const Eigen::Vector2d nu = -n;
  return penalty_force(nu.dot(u), g, r) * nu;
}

/// \f$ r H(u_n - g) \nu\nu^T \f$.
inline Eigen::Matrix2d penalty_tangent(const Eigen::Vector2d& u, const Eigen::Vector2d& n, double g,
                                       double r) {
  const Eigen::Vector2d nu = -n;
  const Eigen::Matrix2d nu_nu = nu * nu.transpose();
  return d_penalty_force(nu.dot(u), g, r) * nu_nu;
}

} // namespace sig
