// The small-strain first iterate of a large-deformation solve (small_strain_start.hpp).
#include "stages/small_strain_start.hpp"

#include "assembly/system.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "stages/static_solve.hpp"

#include <chrono>

namespace sig {

std::string StartRecord::name() const {
  return !used ? "rest" : fraction > 0 ? "small-strain" : "rest (fallback)";
}

StartRecord start_from_small_strain(FiniteStrainBulk& bulk, const FiniteStrainProblem& problem,
                                    double load_factor, ContactSolverParameters parameters,
                                    const std::string& backend) {
  const auto clock = std::chrono::steady_clock::now();
  StartRecord record;
  record.used = true;
  LinearSystem system;
  system.K = bulk.tangent();
  const Eigen::Index ndof = system.K.rows();
  system.f = problem.load.size() ? Eigen::VectorXd(load_factor * problem.load)
                                 : Eigen::VectorXd(Eigen::VectorXd::Zero(ndof));
  system.dirichlet_dofs = problem.dirichlet_dofs;
  system.dirichlet_values = load_factor * problem.dirichlet_values;
  parameters.method = "pdas";
  StaticSolution solution;
  try {
    const bool contact = problem.contact != nullptr && problem.contact->size() > 0;
    solution = contact ? solve_static_contact(system, *problem.contact, parameters, backend)
                       : solve_linear_elasticity(system, backend);
    record.iterations = static_cast<int>(solution.history.size());
    record.converged = solution.converged;
    if (!solution.converged)
      record.note = "the small-strain solve did not converge: " + solution.failure;
  } catch (const Error& e) {
    record.note = std::string("the small-strain solve failed: ") + e.what();
  }
  if (record.converged) {
    record.fraction = bulk.start_from(solution.u);
    record.multiplier = record.fraction * solution.multiplier;
    if (record.fraction == 0)
      record.note = "every fraction of the small-strain solution down to 1/64 inverts a triangle";
  }
  if (!record.note.empty()) log_warning("large deformation starts from rest: " + record.note);
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return record;
}

} // namespace sig
