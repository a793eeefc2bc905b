#include "integrator/finite_strain_march.hpp"

#include "assembly/nonlinear.hpp"
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "integrator/contact_strategy.hpp"
#include "mesh/mesh.hpp"

#include <sstream>

namespace sig {

namespace {

/// The contact nodes' penetration q_n = -d(x) and normal velocity -n(x) . v at the state (u, v).
void contact_state(const FiniteStrainProblem& problem, const Eigen::VectorXd& u,
                   const Eigen::VectorXd& v, Eigen::VectorXd& q, Eigen::VectorXd& v_n) {
  const int m = problem.contact ? problem.contact->size() : 0;
  q.resize(m);
  v_n.resize(m);
  for (int p = 0; p < m; ++p) {
    const int node = problem.contact->node[p];
    const Eigen::Vector2d x = problem.mesh->nodes[node] + u.segment<2>(2 * node);
    q[p] = -problem.obstacle->signed_distance(x);
    v_n[p] = -problem.obstacle->normal(x).dot(v.segment<2>(2 * node));
  }
}

/// A step without contact elements: the driver on no contact node, unless the predictor already
/// solves it.
ContactStepSolution bulk_step(FiniteStrainBulk& bulk, const HyperelasticMarchOptions& options) {
  ContactStepSolution s;
  s.normal_force = s.tangential_force = Eigen::VectorXd::Zero(0);
  const Eigen::VectorXd none(0);
  if (bulk.equilibrium_residual(none, none) <= options.eps * bulk.force_scale()) {
    s.converged = true;
    return s;
  }
  ContactSolverParameters parameters;
  parameters.eps = options.eps;
  parameters.max_iterations = options.max_iterations;
  const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
  ContactIterate iterate;
  const ContactNewtonResult r =
      solve_contact(bulk, ContactSetting{}, *method, newton_options(parameters, {}), iterate);
  s.converged = r.converged;
  s.failure = r.failure;
  s.iterations = r.iterations();
  return s;
}

} // namespace

MarchHistory march_hyperelastic(const FiniteStrainProblem& problem, const ContactStrategy* strategy,
                                const HyperelasticMarchOptions& options,
                                const DynamicState& initial, int steps, int output_every,
                                const StepObserver& observer) {
  SIG_VERIFY(steps >= 0 && output_every >= 0,
             "march: " << steps << " steps, output_every = " << output_every);
  SIG_VERIFY(problem.mass && problem.mesh, "hyperelastic march: no mass");
  const int m = problem.contact ? problem.contact->size() : 0;
  SIG_VERIFY(m == 0 || strategy, "hyperelastic march: contact elements without a strategy");
  const ContactSetting setting =
      m > 0 ? ContactSetting{problem.contact->law, problem.contact->weight} : ContactSetting{};
  FiniteStrainBulk bulk(problem, options.backend, options.eps);
  const Eigen::SparseMatrix<double>& M = *problem.mass;
  const double k = problem.time_step;
  const Eigen::VectorXd load =
      problem.load.size() ? problem.load : Eigen::VectorXd::Zero(initial.u.size());

  const auto record_of = [&](const DynamicState& state, int n, double elastic,
                             double external_work) {
    EnergyRecord r;
    r.step = n;
    r.time = state.time;
    r.kinetic = 0.5 * state.v.dot(M * state.v);
    r.elastic = elastic;
    r.total = r.kinetic + r.elastic;
    r.external_work = external_work;
    return r;
  };
  MarchHistory history;
  history.energy.reserve(static_cast<std::size_t>(steps) + 1);
  Eigen::VectorXd q_now, v_n;
  contact_state(problem, initial.u, initial.v, q_now, v_n);
  history.energy.push_back(record_of(
      initial, 0, hyperelastic_energy(*problem.mesh, *problem.materials, initial.u), 0.0));
  history.energy.back().max_penetration = m > 0 ? std::max(q_now.maxCoeff(), 0.0) : 0.0;
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(m);
  const auto keep = [&](const DynamicState& state, const Eigen::VectorXd& N,
                        const Eigen::VectorXd& T) {
    history.outputs.push_back(state);
    if (m == 0) return;
    history.output_pressure.push_back(N.cwiseQuotient(setting.weight));
    if (setting.has_friction())
      history.output_tangential_pressure.push_back(T.cwiseQuotient(setting.weight));
  };
  keep(initial, none, none);

  DynamicState state = initial;
  Eigen::VectorXd N = none, T = none;
  bool last_kept = true;
  for (int n = 1; n <= steps; ++n) {
    bulk.start_time_step(state.u, state.v);
    ContactStepSolution step;
    if (m > 0)
      step = strategy->solve(bulk, setting, ContactStepStart{q_now, v_n, k});
    else
      step = bulk_step(bulk, options);
    if (!step.converged) {
      std::ostringstream why;
      why << "step " << n << " (t = " << state.time + k
          << "): " << (m > 0 ? strategy->name() : std::string("the Newton method"))
          << " did not converge after " << step.iterations << " iterations: " << step.failure;
      history.converged = false;
      history.failure = why.str();
      break;
    }
    DynamicState next{state.time + k, bulk.displacement(), bulk.velocity()};
    EnergyRecord record =
        record_of(next, n, bulk.strain_energy(),
                  history.energy.back().external_work + load.dot(next.u - state.u));
    Eigen::VectorXd q_next;
    contact_state(problem, next.u, next.v, q_next, v_n);
    if (m > 0) {
      N = step.normal_force;
      T = step.tangential_force;
      add_contact_step(record, history.energy.back(), N, T, q_now, q_next, bulk.slip(),
                       interface_energy(step.law, setting.weight, q_next));
    }
    record.newton_iterations = step.iterations;
    history.energy.push_back(record);
    state = std::move(next);
    q_now = q_next;
    last_kept = output_every > 0 ? n % output_every == 0 : n == steps;
    if (last_kept) keep(state, N, T);
    if (observer) observer(state, history.energy.back());
  }
  if (!last_kept) keep(state, N, T); // a march stopped early keeps its last good state
  history.final_state = state;
  return history;
}

} // namespace sig
