#pragma once
// Static frictionless contact of a hyperelastic body in large deformation (thesis ch. 7, Scene
// 7b): at each load step a generalized (semi-smooth) Newton method on the sparse system
//
//   R(u, lambda) = f_int(u) - s f_ext - sum_p lambda_p n_p = 0   on the free dofs,
//   C_p(lambda_p / w_p, phi_p(u)) = 0                            per contact node,
//
// with u = s u_D on the Dirichlet dofs (s = k / steps), f_int the hyperelastic internal force
// (assembly/nonlinear.hpp) and phi_p = -d(X_p + u_p) - (g_p - d(X_p)) the penetration of the
// CURRENT position of node p into the obstacle (it plays u_n - g of the small-strain solvers,
// contact_problem.hpp; g_p - d(X_p) keeps a CONTACT card's extra gap). The normal n_p is the
// obstacle's normal at the current position (the foundation's normal, thesis Remark 1.1).
//
// Each Newton step works in nodal frames (t_p, -n_p) at the contact nodes, so the normal
// displacement increment is one unknown, and the four methods of contact_solver.hpp act on it
// exactly as in the small-strain classes:
//   pdas        active iff pressure + gamma phi >= 0 (3.29); active: du_n = -phi (held as a
//               Dirichlet value, the multiplier is the reaction); inactive: lambda = 0
//   alm         the same test with r (3.10), multipliers as unknowns (the Lagrange nodes,
//               eliminated as in augmented_lagrangian.cpp); no active-set condition in the stop
//   projection  active iff phi + c pressure >= 0 (7.19) with the pressure of nodes left inactive
//               taken as 0; inactive nodes get the Robin spring w / c on their normal (7.22)
//   penalty     lambda = w r [phi]_+, a spring w r on the nodes with phi >= 0 (Remark 3.2)
// The Jacobian is consistent for any obstacle whose d is the true distance (grad d = n): the
// constraint rows use n, and the contact force lambda_p n(x_p) adds -lambda_p dn/dx (the
// obstacle's curvature, zero for a plane) to the tangent; dn/dx is a central difference of
// Obstacle::normal, since the obstacle interface offers n only.
//
// Line search: the step (du, dlambda) is scaled by alpha = 1, 1/2, 1/4, ... (at most
// kMaxHalvings times) until the body has no inverted triangle (hyperelastic_energy finite) and
// the residual norm decreases. If no alpha decreases it, the largest admissible alpha is taken
// (active-set changes may raise the residual for one step; the stopping test still needs a
// small residual); at the first iteration of a load step, whose iterate already met the
// residual test at the previous load (the new Dirichlet values are not in R), no decrease is
// sought and that alpha is taken at once. If even the smallest alpha inverts a triangle the load
// step stops ("Nv").
//
// Cost: the Newton matrix keeps ONE sparsity pattern for the whole solve, so the linear solver's
// symbolic analysis is done once and an iteration costs one numeric factorization + solve plus
// the bulk assemblies of its line search. The frames are applied in place to the tangent's
// values (Q^T K Q has K's pattern); the normal dofs held by the active set are not eliminated
// but decoupled (row and column zeroed, diagonal kept), which gives the elimination's solution
// on a fixed pattern. The first trial of a line search is assembled with its tangent, the later
// ones with the force only (the accepted one gets its tangent when the next iteration needs it).
// LoadStepResult::bulk_evaluations counts the assemblies (drivers/bench-ring.sh reports them).
//
// Stop (test (iv)): relative increment of (u, lambda) <= eps, relative residual <= eps, the
// Dirichlet values of the step reached, and (except alm) the active set unchanged. The residual
// is relative to max(||s f_ext||, ||f_int(u)||), f_int over every dof (it holds the reactions,
// so an imposed-displacement problem without load has a scale). Non-convergence is a returned
// status with its history; the later load steps are then not attempted.
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "solver/contact_solver.hpp"

#include <string>
#include <vector>

namespace sig {

struct Mesh;
struct MaterialTable;

/// The data of the hyperelastic contact problem at the final load (scaled by k / steps at step
/// k). The contact nodes must carry no Dirichlet condition.
struct FiniteStrainProblem {
  const Mesh* mesh = nullptr;
  const MaterialTable* materials = nullptr; ///< every sub-domain hyperelastic
  std::vector<int> dirichlet_dofs;          ///< sorted, unique, dof = 2 node + component
  Eigen::VectorXd dirichlet_values;         ///< imposed displacement at the final step
  Eigen::VectorXd load;                     ///< external nodal force at the final step (or empty)
  const ContactElements* contact = nullptr; ///< may be null or empty: no contact
  const Obstacle* obstacle = nullptr;       ///< required when there are contact elements
};

struct FiniteStrainOptions {
  ContactSolverParameters contact; ///< method, r / gamma / c, eps, max_iterations per step
  int load_steps = 1;
  std::string backend = "umfpack"; ///< cholmod (spd tangent only) | umfpack | mumps
};

struct LoadStepResult {
  double load_factor = 0; ///< s = k / steps
  bool converged = false;
  std::string failure; ///< why the step stopped without converging
  std::vector<IterationRecord> history;
  std::vector<double> step_length; ///< line-search alpha per iteration
  Eigen::VectorXd u;               ///< full displacement at the end of the step
  Eigen::VectorXd multiplier;      ///< nodal contact forces lambda_p (pressure = lambda / w)
  std::vector<char> active;
  /// Hyperelastic assemblies (line-search trials and tangents of accepted force-only trials):
  /// with the factorizations, the cost of the step.
  int bulk_evaluations = 0;
  int iterations() const { return static_cast<int>(history.size()); }
};

struct FiniteStrainSolution {
  std::vector<LoadStepResult> steps; ///< the attempted steps; stops after the first failure
  int unknowns = 0;                  ///< Newton vector size (dofs, plus multipliers for alm)
  bool converged() const;            ///< every requested step attempted and converged
  int total_iterations() const;
};

/// Semi-smooth Newton with load stepping (above). sig::Error for inconsistent input (sizes, a
/// Dirichlet contact node, an unknown method or backend); non-convergence is returned.
FiniteStrainSolution solve_finite_strain_contact(const FiniteStrainProblem& problem,
                                                 const FiniteStrainOptions& options);

} // namespace sig
