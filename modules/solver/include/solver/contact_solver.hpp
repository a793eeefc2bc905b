#pragma once
// The nonlinear contact solvers of the thesis, one class per method and file:
//   augmented_lagrangian.cpp  Alart-Curnier augmented Lagrangian, generalized Newton on (u, lambda)
//                             with the Lagrange nodes as extra unknowns (3.7)-(3.11)
//   penalty.cpp               penalty, the foundation as a spring of stiffness r (Remark 3.2)
//   primal_dual_active_set.cpp  PDAS (3.20)-(3.32)
//   iterative_projection.cpp  iterative projection with the Robin condition (7.16)-(7.22)
// Every method stops with test (iv): relative increment <= eps, relative residual <= eps and the
// active set unchanged (ALM: the thesis's test (iii), without the active set). Non-convergence is a
// result ("Nv"), returned with its history.
#include "solver/contact_problem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sig {

struct ContactSolverParameters {
  std::string method = "pdas"; ///< alm | penalty | pdas | projection
  double r = 100;              ///< ALM augmentation / penalty stiffness
  double gamma = 100;          ///< PDAS
  double c = 100;              ///< projection
  double eps = 1e-5;           ///< stopping tolerance of test (iv)
  int max_iterations = 100;
};

struct IterationRecord {
  int active = 0;       ///< size of the active set used by the iteration
  double residual = 0;  ///< relative residual after the iteration
  double increment = 0; ///< relative increment ||x(k+1) - x(k)|| / ||x(k+1)||
  double step = 0;      ///< E_k = ||x(k+1) - x(k)||, the measure of the thesis's Figs 7.14-7.16
};

struct ContactSolution {
  Eigen::VectorXd u;
  Eigen::VectorXd multiplier; ///< nodal contact forces lambda_p >= 0
  std::vector<char> active;   ///< final contact status per element
  bool converged = false;
  std::string failure; ///< why it stopped without converging
  std::vector<IterationRecord> history;
  int iterations() const { return static_cast<int>(history.size()); }
  /// Unknowns of the Newton vector x: displacements, plus multipliers for ALM.
  int unknowns = 0;
};

class ContactSolver {
public:
  virtual ~ContactSolver() = default;
  virtual ContactSolution solve(const ContactProblem& problem) const = 0;
  virtual std::string name() const = 0;
};

/// sig::Error for an unknown method name.
std::unique_ptr<ContactSolver> make_contact_solver(const ContactSolverParameters& parameters);

/// Residual of equilibrium, relative to the load: ||K u + E^T lambda - f|| / ||f||.
double equilibrium_residual(const ContactProblem& problem, const Eigen::VectorXd& u,
                            const Eigen::VectorXd& multiplier);

/// The change of the Newton vector over one iteration: its norm E_k and, for test (iv), its
/// ratio to the new vector, ||now - before|| / max(||now||, tiny).
struct Increment {
  double norm = 0;
  double relative = 0;
};
Increment increment_between(const Eigen::VectorXd& now, const Eigen::VectorXd& before);

} // namespace sig
