#pragma once
// The contact problem as the nonlinear solvers see it: algebra only, no mesh (the contact stage
// has already turned the geometry into normals, gaps and weights).
//
// Unknowns are expressed in nodal frames (tangent, normal) at the contact nodes, so that the
// normal displacement u_n,p of contact element p is one unknown, u[normal_dof[p]], positive
// towards the obstacle. The Signorini condition (1.22) then bounds one coordinate,
// u_n,p <= g_p, and an active node is a Dirichlet condition on that coordinate, as in deal.II
// step-41. Equilibrium reads K u + E^T lambda = f, where E picks the normal unknowns and
// lambda_p >= 0 is the nodal contact force (the thesis's A(u) + lambda_nu nu = f, (7.17)).
// The complementarity functions act on the contact pressure lambda_p / w_p, w_p the nodal
// weight (tributary length), as the thesis's multipliers are densities in Y_nu^h: so r, gamma
// and c keep their meaning (GPa/m, m/GPa) whatever the mesh.
#include <Eigen/Dense>
#include <vector>

namespace sig {

struct ContactProblem {
  Eigen::MatrixXd K;           ///< symmetric positive semi-definite (semi-coercive problems)
  Eigen::VectorXd f;           ///< load
  std::vector<int> normal_dof; ///< per contact element, its normal unknown
  Eigen::VectorXd gap;         ///< g_p
  Eigen::VectorXd weight;      ///< w_p > 0: pressure = lambda_p / w_p
  /// Weight of the proximal term eps (u - u_previous) added to every linear step. It makes the
  /// steps of a semi-coercive problem well posed (a single contact node leaves a rotation free)
  /// and vanishes at convergence, where u = u_previous.
  double regularization = 0;

  int size() const { return static_cast<int>(f.size()); }
  int contacts() const { return static_cast<int>(normal_dof.size()); }
  /// Normal displacements u_n,p of a state u.
  Eigen::VectorXd normal_part(const Eigen::VectorXd& u) const;
};

/// One linear step shared by all methods: solve
///   (K + diag(normal_stiffness on normal dofs) + eps I) u = f + E^T normal_load + eps u_previous
/// with u_n,p = g_p imposed on the elements marked `imposed`. Returns false if the step matrix is
/// not positive definite (the method then reports non-convergence, never a wrong number).
struct LinearStep {
  Eigen::VectorXd u;
  /// Per element: the force E u-row needs to hold u_n,p = g_p (the multiplier of an imposed
  /// node); 0 where nothing is imposed.
  Eigen::VectorXd reaction;
};
bool solve_linear_step(const ContactProblem& problem, const std::vector<char>& imposed,
                       const Eigen::VectorXd& normal_stiffness, const Eigen::VectorXd& normal_load,
                       const Eigen::VectorXd& u_previous, LinearStep& step);

} // namespace sig
