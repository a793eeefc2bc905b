#include "integrator/elastodynamic_march.hpp"

#include "core/error.hpp"
#include "integrator/contact_strategy.hpp"
#include "solver/condensed_bulk.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace sig {

namespace {

/// Empty, or why the displacement u brings a watched node (one outside the candidate zone)
/// beyond the obstacle surface.
std::string watched_entry(const ContactBoundary& boundary, const Eigen::VectorXd& u) {
  if (boundary.watched.rows() == 0) return {};
  const Eigen::VectorXd q = boundary.watched * u - boundary.watched_gap;
  Eigen::Index worst = 0;
  if (q.maxCoeff(&worst) <= 0.0) return {};
  std::ostringstream why;
  why << "contact node " << boundary.watched_nodes[static_cast<std::size_t>(worst)] + 1
      << ", one of the " << q.size() << " outside the candidate zone (initial gap "
      << boundary.watched_gap[worst] << ") penetrates the obstacle by " << q[worst]
      << ": raise SOLVER candidate_gap= so that the zone holds every node the contact reaches";
  return why.str();
}

} // namespace

ElastodynamicSteps::ElastodynamicSteps(const TimeScheme& scheme, DynamicState initial)
    : scheme_(scheme), state_(std::move(initial)), products_(scheme_.products(state_)) {
  scheme_.factorize(); // here, not in the first step: a failure before the march starts
}

ElastodynamicSteps::ElastodynamicSteps(const TimeScheme& scheme, const ContactBoundary& boundary,
                                       const ContactStrategy& strategy, DynamicState initial)
    : scheme_(scheme), boundary_(&boundary), strategy_(&strategy), state_(std::move(initial)),
      products_(scheme_.products(state_)) {
  SIG_VERIFY(boundary.size() > 0, "march: a contact boundary without nodes");
  SIG_VERIFY(boundary.B.cols() == scheme.problem().num_dofs(),
             "march: the contact boundary has " << boundary.B.cols() << " dofs, the problem "
                                                << scheme.problem().num_dofs());
  SIG_VERIFY((boundary.tangential.rows() == boundary.size() ||
              boundary.tangential.rows() == 2 * boundary.size()) &&
                 boundary.tangential.cols() == boundary.B.cols(),
             "march: a tangential operator of "
                 << boundary.tangential.rows() << " x " << boundary.tangential.cols() << " for "
                 << boundary.size() << " contact nodes (one or two tangents each)");
  SIG_VERIFY(boundary.watched.rows() == boundary.watched_gap.size() &&
                 std::ssize(boundary.watched_nodes) == boundary.watched.rows() &&
                 (boundary.watched.rows() == 0 || boundary.watched.cols() == boundary.B.cols()),
             "march: " << boundary.watched.rows() << " x " << boundary.watched.cols()
                       << " watched rows for " << boundary.watched_gap.size() << " gaps");
  condensed_.emplace(scheme, boundary);
  const int p = boundary.size();
  normal_dof_.resize(p);
  std::iota(normal_dof_.begin(), normal_dof_.end(), 0);
  if (condensed_->G().rows() > p) {
    tangential_dof_.resize(condensed_->G().rows() - p); // d - 1 per node, node i's at (d - 1) i
    std::iota(tangential_dof_.begin(), tangential_dof_.end(), p);
  }
  x_now_ = condensed_->G() * state_.u;
  q_now_ = x_now_.head(p) - boundary.geometric_gap;
}

ElastodynamicSteps::~ElastodynamicSteps() = default;

StepRecord ElastodynamicSteps::start() const {
  StepRecord r;
  r.time = state_.time;
  r.energy = scheme_.energy(state_, products_);
  if (boundary_ != nullptr) {
    // No secant law before the first step: no interface energy.
    r.energy.max_penetration = std::max(q_now_.maxCoeff(), 0.0);
    const int p = boundary_->size();
    r.contact.normal_force = Eigen::VectorXd::Zero(p);
    // d - 1 per node with friction (3D: two), one without.
    r.contact.tangential_force =
        Eigen::VectorXd::Zero(tangential_dof_.empty() ? p : std::ssize(tangential_dof_));
  }
  return r;
}

StepRecord ElastodynamicSteps::step(int) {
  const double k = scheme_.time_step();
  StepRecord r;
  r.time = state_.time + k;
  r.iterations = 1;
  const Eigen::VectorXd f_bar = scheme_.step_load(state_.time);
  DynamicState next;
  TimeScheme::StateProducts next_products;
  if (boundary_ != nullptr) {
    const ContactBoundary& boundary = *boundary_;
    const int p = boundary.size();
    // 1. The step without contact force, on the components: w_free = S_c^{-1} g (the forward
    //    half of the step's solve).
    const Eigen::VectorXd g = condensed_->condense(scheme_.step_right_side(products_, f_bar));
    const Eigen::VectorXd w_free = condensed_->solve(g);

    // 2. The strategy's forces at the end of the step, on the step condensed onto the normal
    //    displacements and the slips (dynamic_contact.hpp) written for the increment
    //    w = x - x_now: A w + lambda = A w_free = g / 2, q_n = w_n - (d - x_now,n), the slip
    //    w_t the tangential displacement over the step; starting from the free step. In free
    //    flight the strategy's first test finds the free step to be the step (no Newton
    //    iteration, no force): the restarted bulk costs a product with A and that test.
    const ContactStepStart start{q_now_, boundary.B * state_.v, k};
    const Eigen::VectorXd gap = boundary.geometric_gap - x_now_.head(p);
    // One bulk for the march (A does not change): its dense factor is kept from step to step.
    if (bulk_) {
      bulk_->restart(0.5 * g, gap, w_free);
    } else {
      CondensedProblem problem;
      problem.S = condensed_->A();
      problem.f = 0.5 * g;
      problem.normal_dof = normal_dof_;
      problem.tangential_dof = tangential_dof_;
      problem.gap = gap;
      bulk_ = std::make_unique<CondensedBulk>(std::move(problem), Eigen::VectorXd{}, w_free);
    }
    const ContactStepSolution forces = strategy_->solve(*bulk_, boundary.setting, start);
    r.iterations = forces.iterations;
    r.contact = contact_record(forces);
    if (!forces.converged) {
      std::ostringstream why;
      why << strategy_->name() << " did not converge after " << forces.iterations
          << " iterations: " << forces.failure;
      r.converged = false;
      r.failure = why.str();
      return r;
    }

    // 3. Their response, exactly: w = S_c^{-1} (g - 2 lambda), and the increment of the whole
    //    body with those components (the backward half). In free flight lambda = 0 and the free
    //    step is the step.
    Eigen::VectorXd lambda = forces.normal_force;
    const auto slips = std::ssize(tangential_dof_);
    if (slips > 0) {
      lambda.resize(p + slips);
      lambda << forces.normal_force, forces.tangential_force;
    }
    const bool pushed = (lambda.array() != 0.0).any();
    r.free_flight = forces.iterations == 0 && !pushed;
    const Eigen::VectorXd w =
        pushed ? Eigen::VectorXd(condensed_->solve(g - 2.0 * lambda)) : w_free;
    next = scheme_.after_increment(state_, condensed_->increment(w));
    if (const std::string entered = watched_entry(boundary, next.u); !entered.empty()) {
      r.converged = false;
      r.failure = entered;
      return r;
    }
    const Eigen::VectorXd x_next = condensed_->G() * next.u;
    const Eigen::VectorXd q_next = x_next.head(p) - boundary.geometric_gap;
    const Eigen::VectorXd slip = slips == 0
                                     ? Eigen::VectorXd(Eigen::VectorXd::Zero(p))
                                     : Eigen::VectorXd(x_next.tail(slips) - x_now_.tail(slips));
    r.work.load = f_bar.dot(next.u - state_.u);
    next_products = scheme_.products(next);
    r.energy = scheme_.energy(next, next_products);
    add_contact_step(r.energy, r.work, forces.normal_force, forces.tangential_force, q_now_, q_next,
                     slip, interface_energy(forces.law, boundary.setting.weight, q_next));
    x_now_ = x_next;
    q_now_ = q_next;
  } else {
    next = scheme_.after_increment(
        state_, scheme_.solve_step_operator(scheme_.step_right_side(products_, f_bar)));
    r.work.load = f_bar.dot(next.u - state_.u);
    next_products = scheme_.products(next);
    r.energy = scheme_.energy(next, next_products);
  }
  state_ = std::move(next);
  products_ = std::move(next_products);
  return r;
}

std::string ElastodynamicSteps::ordering() const {
  return condensed_ ? condensed_->ordering() : scheme_.ordering();
}

MarchHistory march(const TimeScheme& scheme, const DynamicState& initial, int steps,
                   int output_every, const StepObserver& observer) {
  ElastodynamicSteps hook(scheme, initial);
  return march(hook, steps, output_every, observer);
}

MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every, const StepObserver& observer) {
  ElastodynamicSteps hook(scheme, boundary, strategy, initial);
  return march(hook, steps, output_every, observer);
}

} // namespace sig
