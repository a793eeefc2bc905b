#include "stages/finite_strain_march.hpp"

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
  const int d = problem.mesh->dim;
  for (int p = 0; p < m; ++p) {
    const int node = problem.contact->node[p];
    const Point x = problem.mesh->nodes[node] + u.segment(d * node, d);
    const Point n = problem.obstacle->normal(x);
    q[p] = -problem.obstacle->signed_distance(x);
    // -n . v by components (Eigen's dot of a Point trips GCC's -Warray-bounds: it cannot see
    // that a Point holds at most 3).
    v_n[p] = 0.0;
    for (int i = 0; i < d; ++i)
      v_n[p] -= n[i] * v[d * node + i];
  }
}

/// A step without contact elements: the driver on no contact node, unless the predictor already
/// solves it.
ContactStepSolution bulk_step(FiniteStrainBulk& bulk, const HyperelasticMarchOptions& options) {
  ContactStepSolution s;
  s.converged = predictor_solves_step(bulk, ContactSetting{}, options.eps);
  if (s.converged) return s;
  ContactSolverParameters parameters;
  parameters.eps = options.eps;
  parameters.max_iterations = options.max_iterations;
  const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
  ContactIterate iterate;
  const ContactNewtonResult r =
      solve_contact(bulk, ContactSetting{}, *method, newton_options(parameters), iterate);
  s.converged = r.converged;
  s.failure = r.failure;
  s.iterations = r.iterations();
  return s;
}

/// `problem`, checked before a bulk is built on it.
const FiniteStrainProblem& with_mass(const FiniteStrainProblem& problem) {
  SIG_VERIFY(problem.mass && problem.mesh, "hyperelastic march: no mass");
  return problem;
}

} // namespace

HyperelasticSteps::HyperelasticSteps(const FiniteStrainProblem& problem,
                                     const ContactStrategy* strategy,
                                     const HyperelasticMarchOptions& options,
                                     const DynamicState& initial)
    : problem_(with_mass(problem)), strategy_(strategy), options_(options),
      m_(problem.contact ? problem.contact->size() : 0),
      setting_(m_ > 0 ? ContactSetting{problem.contact->law, problem.contact->weight}
                      : ContactSetting{}),
      bulk_(problem, options.backend, options.eps), state_(initial),
      load_(problem.load.size() ? problem.load : Eigen::VectorXd::Zero(initial.u.size())) {
  SIG_VERIFY(m_ == 0 || strategy_, "hyperelastic march: contact elements without a strategy");
  contact_state(problem_, state_.u, state_.v, q_now_, v_n_);
}

EnergyRecord HyperelasticSteps::energies(const DynamicState& state, double elastic) const {
  EnergyRecord e;
  e.kinetic = 0.5 * state.v.dot(*problem_.mass * state.v);
  e.elastic = elastic;
  e.total = e.kinetic + e.elastic;
  return e;
}

StepRecord HyperelasticSteps::start() const {
  StepRecord r;
  r.time = state_.time;
  r.energy = energies(state_, hyperelastic_energy(*problem_.mesh, *problem_.materials, state_.u));
  r.energy.max_penetration = m_ > 0 ? std::max(q_now_.maxCoeff(), 0.0) : 0.0;
  if (m_ > 0) {
    r.contact.normal_force = Eigen::VectorXd::Zero(m_);
    r.contact.tangential_force = Eigen::VectorXd::Zero(bulk_.slip().size()); // d - 1 a node
  }
  return r;
}

StepRecord HyperelasticSteps::step(int) {
  const double k = problem_.time_step;
  StepRecord r;
  r.time = state_.time + k;
  bulk_.start_time_step(state_.u, state_.v);
  const ContactStepSolution step =
      m_ > 0 ? strategy_->solve(bulk_, setting_, ContactStepStart{q_now_, v_n_, k})
             : bulk_step(bulk_, options_);
  r.iterations = step.iterations;
  if (m_ > 0) r.contact = contact_record(step);
  if (!step.converged) {
    std::ostringstream why;
    why << (m_ > 0 ? strategy_->name() : std::string("the Newton method"))
        << " did not converge after " << step.iterations << " iterations: " << step.failure;
    r.converged = false;
    r.failure = why.str();
    return r;
  }
  DynamicState next{state_.time + k, bulk_.displacement(), bulk_.velocity()};
  r.energy = energies(next, bulk_.strain_energy());
  r.work.load = load_.dot(next.u - state_.u);
  Eigen::VectorXd q_next;
  contact_state(problem_, next.u, next.v, q_next, v_n_);
  if (m_ > 0)
    add_contact_step(r.energy, r.work, step.normal_force, step.tangential_force, q_now_, q_next,
                     bulk_.slip(), interface_energy(step.law, setting_.weight, q_next));
  state_ = std::move(next);
  q_now_ = q_next;
  return r;
}

MarchHistory march_hyperelastic(const FiniteStrainProblem& problem, const ContactStrategy* strategy,
                                const HyperelasticMarchOptions& options,
                                const DynamicState& initial, int steps, int output_every,
                                const StepObserver& observer) {
  HyperelasticSteps hook(problem, strategy, options, initial);
  return march(hook, steps, output_every, observer);
}

} // namespace sig
