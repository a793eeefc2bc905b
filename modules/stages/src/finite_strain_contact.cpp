// Load stepping of the large-deformation contact solve (finite_strain_contact.hpp).
#include "stages/finite_strain_contact.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "mesh/mesh.hpp"
#include "stages/newton_outcome.hpp"

#include <algorithm>

namespace sig {

bool FiniteStrainSolution::converged() const {
  return !steps.empty() &&
         std::all_of(steps.begin(), steps.end(), [](const auto& s) { return s.converged; });
}

int FiniteStrainSolution::total_iterations() const {
  int n = 0;
  for (const LoadStepResult& s : steps)
    n += s.iterations();
  return n;
}

FiniteStrainSolution solve_finite_strain_contact(const FiniteStrainProblem& problem,
                                                 const FiniteStrainOptions& options) {
  SIG_VERIFY(options.load_steps >= 1, "load_steps must be >= 1, not " << options.load_steps);
  FiniteStrainProblem checked = problem;
  if (problem.contact && problem.contact->size() == 0) checked.contact = nullptr;
  ContactSetting setting;
  if (checked.contact) {
    setting = {checked.contact->law, checked.contact->weight};
    SIG_VERIFY(!setting.has_friction(),
               "friction in large deformation is not implemented: the hyperelastic solve is "
               "frictionless (remove the FRICTION card)");
  }
  const std::unique_ptr<ContactMethod> method = make_contact_method(options.contact);
  FiniteStrainBulk bulk(checked, options.backend, options.contact.eps);

  FiniteStrainSolution solution;
  solution.unknowns = static_cast<int>(bulk.displacement().size()) +
                      setting.size() * method->multiplier_unknowns(false);
  if (options.small_strain_start)
    solution.start = start_from_small_strain(bulk, checked, 1.0 / options.load_steps,
                                             options.contact, options.backend);
  ContactIterate iterate;
  if (solution.start.multiplier.size() == setting.size())
    iterate.lambda = solution.start.multiplier;
  for (int k = 1; k <= options.load_steps; ++k) {
    const double s = static_cast<double>(k) / options.load_steps;
    bulk.set_load_factor(s);
    const int evaluations = bulk.evaluations();
    ContactNewtonResult c =
        solve_contact(bulk, setting, *method, newton_options(options.contact), iterate);
    // The small-strain start is a guess. Where the backend cannot factorize the tangent there
    // (CHOLMOD: not positive definite, a state the linear crush overshoots to, unstable, not the
    // solution's; the hollow ball of datafiles/scene3d/crush.dat pressed by 0.6 of its radius),
    // the step starts again from rest, said as a fallback.
    if (k == 1 && solution.start.fraction > 0 && !c.converged && c.history.empty() &&
        c.reason == NewtonFailure::singular_step) {
      solution.start.note =
          "the tangent at the small-strain start cannot be factorized (" + c.failure + ")";
      log_warning("large deformation starts from rest: " + solution.start.note);
      solution.start.fraction = 0;
      solution.start.multiplier.resize(0);
      bulk.start_from(Eigen::VectorXd::Zero(bulk.displacement().size()));
      iterate = ContactIterate{};
      c = solve_contact(bulk, setting, *method, newton_options(options.contact), iterate);
    }
    LoadStepResult step;
    step.load_factor = s;
    record_newton_outcome(step, c);
    step.step_length = c.step_length;
    step.u = bulk.displacement();
    step.multiplier = c.normal_force;
    step.normal_status = c.normal_status;
    step.bulk_evaluations = bulk.evaluations() - evaluations;
    solution.steps.push_back(step);
    if (!step.converged) break; // later steps start from a wrong state
  }
  return solution;
}

} // namespace sig
