#pragma once
// Static frictionless contact of a hyperelastic body in large deformation (thesis ch. 7, Scene
// 7b): load steps s = k / steps, each solved by the one contact Newton driver
// (solver/contact_newton.hpp) on the hyperelastic bulk (stages/finite_strain_bulk.hpp), the
// first from the small-strain solution of its problem (small_strain_start.hpp) or from rest,
// the others warm-started from the previous step's state and statuses:
//
//   f_int(u) - s f_ext - sum_p N_p n_p = 0   on the free dofs,   u = s u_D on the Dirichlet dofs,
//   the contact law of each node in its penetration q_n = -d(X_p + u_p)   (contact_kernel.hpp).
//
// The four methods act as in the small-strain solve: pdas and alm impose dq_n = g - q_n on the
// active nodes (the multiplier is the reaction), projection adds its Robin spring w / c on the
// inactive ones, penalty a spring w r on the penetrating ones. A step length is searched:
// alpha = 1, 1/2, ... until the body has no inverted triangle and ||R|| decreases (see
// contact_newton.cpp). Stop (test (iv)): relative increment of (u, lambda) <= eps, relative
// residual <= eps, the Dirichlet values of the step reached, and (except alm) the statuses
// unchanged; the residual is relative to max(||s f_ext||, ||f_int(u)||), f_int over every dof
// (it holds the reactions, so an imposed-displacement problem without load has a scale).
// Non-convergence is a returned status with its history; the later load steps are then not
// attempted.
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"
#include "stages/finite_strain_bulk.hpp"
#include "stages/small_strain_start.hpp"

#include <string>
#include <vector>

namespace sig {

struct FiniteStrainOptions {
  ContactSolverParameters contact; ///< method, r / gamma / c, eps, max_iterations per step
  int load_steps = 1;
  std::string backend = "umfpack"; ///< cholmod (spd tangent only) | umfpack | mumps
  /// The first load step starts from the small-strain solution of its problem
  /// (small_strain_start.hpp), not from rest.
  bool small_strain_start = true;
};

struct LoadStepResult {
  double load_factor = 0; ///< s = k / steps
  bool converged = false;
  NewtonFailure reason = NewtonFailure::none; ///< why the step stopped without converging
  std::string failure;                        ///< the reason's name and its details
  double drift = 0; ///< with reason drift: the unheld step's length (ContactNewtonResult::drift)
  std::vector<IterationRecord> history;
  std::vector<double> step_length; ///< line-search alpha per iteration
  Eigen::VectorXd u;               ///< full displacement at the end of the step
  Eigen::VectorXd multiplier;      ///< nodal contact forces N_p (pressure = N / w)
  std::vector<NormalStatus> normal_status;
  /// Hyperelastic assemblies (line-search trials and tangents of accepted force-only trials):
  /// with the factorizations, the cost of the step.
  int bulk_evaluations = 0;
  int iterations() const { return static_cast<int>(history.size()); }
};

struct FiniteStrainSolution {
  std::vector<LoadStepResult> steps; ///< the attempted steps; stops after the first failure
  int unknowns = 0;                  ///< Newton vector size (dofs, plus multipliers for alm)
  StartRecord start;                 ///< the first iterate (used = false: rest)
  bool converged() const;            ///< every requested step attempted and converged
  int total_iterations() const;
};

/// Newton with load stepping (above). sig::Error for inconsistent input (sizes, a Dirichlet
/// contact node, an unknown method or backend, a friction law); non-convergence is returned.
FiniteStrainSolution solve_finite_strain_contact(const FiniteStrainProblem& problem,
                                                 const FiniteStrainOptions& options);

} // namespace sig
