#include "stages/finite_strain_stage.hpp"

#include "assembly/nonlinear.hpp"
#include "assembly/system.hpp"
#include "contact/obstacle.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "stages/solution_ds.hpp"

#include <chrono>
#include <cmath>
#include <memory>

namespace sig {

bool has_hyperelastic_law(const MaterialTable& table) {
  for (const SubdomainMaterial& entry : table.entries)
    if (entry.hyperelastic) return true;
  return false;
}

FiniteStrainProblem finite_strain_problem(const Mesh& mesh, const MaterialTable& table,
                                          const LinearSystem& system,
                                          const ContactElements* contact,
                                          std::unique_ptr<Obstacle>& obstacle) {
  if (contact != nullptr && contact->size() > 0) obstacle = make_obstacle(contact->obstacle);
  FiniteStrainProblem problem;
  problem.mesh = &mesh;
  problem.materials = &table;
  problem.dirichlet_dofs = system.dirichlet_dofs;
  problem.dirichlet_values = system.dirichlet_values;
  problem.load = system.f;
  problem.contact = contact;
  problem.obstacle = obstacle.get();
  return problem;
}

FiniteStrainStageResult solve_finite_strain_stage(const Mesh& mesh, const MaterialTable& table,
                                                  const LinearSystem& system,
                                                  const ContactElements* contact,
                                                  const FiniteStrainOptions& options) {
  for (const SubdomainMaterial& entry : table.entries)
    SIG_VERIFY(entry.hyperelastic, "sub-domain " << entry.subdomain
                                                 << " has law=hooke: a large-deformation solve "
                                                    "needs a hyperelastic law everywhere");
  std::unique_ptr<Obstacle> obstacle;
  const FiniteStrainProblem problem = finite_strain_problem(mesh, table, system, contact, obstacle);

  FiniteStrainStageResult result;
  result.dim = mesh.dim;
  if (contact != nullptr) result.contact_weight = contact->weight;
  const auto start = std::chrono::steady_clock::now();
  result.solution = solve_finite_strain_contact(problem, options);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Reactions at the last attempted step: the equilibrium residual f_int - s f_ext on the
  // imposed dofs is what the supports must supply (contact nodes carry no Dirichlet dof).
  // The force alone is needed: one pass, no tangent; a state outside the law's domain (which
  // the assembly refuses) has no reactions.
  if (!result.solution.steps.empty()) {
    const LoadStepResult& last = result.solution.steps.back();
    HyperelasticState state;
    bool admissible = last.u.allFinite();
    try {
      if (admissible) assemble_hyperelastic_force(mesh, table, last.u, state);
    } catch (const Error&) {
      admissible = false;
    }
    if (admissible) {
      const int d = mesh.dim;
      double* component[3] = {&result.reaction_x, &result.reaction_y, &result.reaction_z};
      for (int dof : system.dirichlet_dofs) {
        double r = state.internal_force[dof];
        if (system.f.size() > 0) r -= last.load_factor * system.f[dof];
        *component[dof % d] += r;
        if (d == 3) continue; // the moment about e3 is a 2D body's
        const int node = dof / 2;
        const Eigen::Vector2d x = mesh.nodes[node] + last.u.segment<2>(2 * node);
        result.reaction_moment += dof % 2 == 0 ? -x.y() * r : x.x() * r;
      }
    }
  }
  return result;
}

namespace {

/// The step_* state arrays of write_finite_strain_solution (header): row k = load step k + 1.
void put_load_step_states(Ds& ds, const FiniteStrainStageResult& result) {
  const std::vector<LoadStepResult>& steps = result.solution.steps;
  std::size_t converged = 0;
  while (converged < steps.size() && steps[converged].converged)
    ++converged;
  if (converged == 0) return;
  const Eigen::Index ndof = steps.front().u.size();
  const Eigen::Index m = result.contact_weight.size();
  std::vector<double> u, multiplier, pressure;
  std::vector<std::int64_t> status, normal_status;
  for (std::size_t k = 0; k < converged; ++k) {
    const LoadStepResult& step = steps[k];
    SIG_VERIFY(step.u.size() == ndof && step.u.allFinite(),
               "load step " << k + 1 << ": displacement of size " << step.u.size() << " (expected "
                            << ndof << ") or not finite");
    u.insert(u.end(), step.u.begin(), step.u.end());
    if (m == 0) continue;
    SIG_VERIFY(
        step.multiplier.size() == m && step.normal_status.size() == static_cast<std::size_t>(m),
        "load step " << k + 1 << ": " << step.multiplier.size() << " multipliers and "
                     << step.normal_status.size() << " statuses for " << m << " contact elements");
    for (Eigen::Index i = 0; i < m; ++i) {
      multiplier.push_back(step.multiplier[i]);
      pressure.push_back(step.multiplier[i] / result.contact_weight[i]);
      status.push_back(step.normal_status[i] != NormalStatus::free ? 1 : 0);
      normal_status.push_back(static_cast<std::int64_t>(step.normal_status[i]));
    }
  }
  const auto rows = static_cast<std::int64_t>(converged);
  ds.put("step_u", std::span<const double>(u), {rows, static_cast<std::int64_t>(ndof)});
  if (m == 0) return;
  const std::vector<std::int64_t> shape{rows, static_cast<std::int64_t>(m)};
  ds.put("step_multiplier", std::span<const double>(multiplier), shape);
  ds.put("step_pressure", std::span<const double>(pressure), shape);
  ds.put("step_status", std::span<const std::int64_t>(status), shape);
  ds.put("step_normal_status", std::span<const std::int64_t>(normal_status), shape);
}

} // namespace

void write_finite_strain_solution(const std::filesystem::path& path,
                                  const FiniteStrainStageResult& result, const std::string& method,
                                  const std::string& backend, const std::string& title) {
  const FiniteStrainSolution& solution = result.solution;
  Ds ds("B", title, "sig-solve");
  ds.put_int("finite_strain", 1);
  ds.put_text("method", method);
  ds.put_text("linear", backend);
  ds.put_int("converged", solution.converged() ? 1 : 0);
  ds.put_int("iterations", solution.total_iterations());
  ds.put_int("dofs", solution.unknowns);
  ds.put_int("load_steps", static_cast<std::int64_t>(solution.steps.size()));

  std::vector<double> load;
  std::vector<std::int64_t> step_iterations, step_converged, history_step;
  std::vector<IterationRecord> history;
  std::vector<double> step_length;
  std::string failure;
  NewtonFailure reason = NewtonFailure::none;
  double drift = 0;
  for (std::size_t k = 0; k < solution.steps.size(); ++k) {
    const LoadStepResult& step = solution.steps[k];
    load.push_back(step.load_factor);
    step_iterations.push_back(step.iterations());
    step_converged.push_back(step.converged ? 1 : 0);
    if (!step.converged && failure.empty()) {
      failure = "load step " + std::to_string(k + 1) + ": " + step.failure;
      reason = step.reason;
      drift = step.drift;
    }
    history.insert(history.end(), step.history.begin(), step.history.end());
    step_length.insert(step_length.end(), step.step_length.begin(), step.step_length.end());
    history_step.insert(history_step.end(), step.history.size(), static_cast<std::int64_t>(k + 1));
  }
  ds.put_text("failure", failure);
  put_failure_reason(ds, solution.converged(), reason, drift);
  ds.put("step_load", std::span<const double>(load));
  ds.put("step_iterations", std::span<const std::int64_t>(step_iterations));
  ds.put("step_converged", std::span<const std::int64_t>(step_converged));
  put_history(ds, history);
  ds.put("history_step", std::span<const std::int64_t>(history_step));
  ds.put("history_step_length", std::span<const double>(step_length));
  const StartRecord& start = solution.start;
  ds.put_text("start", start.name());
  if (start.used) {
    ds.put_int("start_iterations", start.iterations);
    ds.put_scalar("start_fraction", start.fraction);
    ds.put_text("start_note", start.note);
    ds.put_scalar("time_start", start.seconds);
  }

  if (!solution.steps.empty()) {
    const LoadStepResult& last = solution.steps.back();
    // A NaN here would flow silently into every report: refuse it where it is made.
    for (Eigen::Index i = 0; i < last.u.size(); ++i)
      SIG_VERIFY(std::isfinite(last.u[i]), path.string()
                                               << ": array 'u' would hold " << last.u[i]
                                               << " at dof " << i + 1 << "; nothing written");
    ds.put("u", std::span<const double>(last.u.data(), last.u.size()));
    if (last.multiplier.size() > 0)
      put_contact_state(
          ds, last.multiplier, Eigen::VectorXd::Zero(last.multiplier.size()), last.normal_status,
          std::vector<FrictionStatus>(last.normal_status.size(), FrictionStatus::none));
  }
  put_load_step_states(ds, result);
  ds.put_scalar("reaction_x", result.reaction_x);
  ds.put_scalar("reaction_y", result.reaction_y);
  if (result.dim == 3)
    ds.put_scalar("reaction_z", result.reaction_z);
  else
    ds.put_scalar("reaction_moment", result.reaction_moment);
  ds.put_scalar("time_solve", result.seconds);
  write_ds(path, ds);
}

} // namespace sig
