// The march in velocity on a linear bulk (linear_contact_march.hpp).
#include "integrator/linear_contact_march.hpp"

#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_bulk.hpp"
#include "solver/contact_condensation.hpp"
#include "solver/linear_solver.hpp"

#include <sstream>

namespace sig {

VelocityContact velocity_contact(const ContactElements& elements, const ReducedSystem& reduced) {
  VelocityContact c;
  for (int p = 0; p < elements.size(); ++p)
    c.dofs.push_back(reduced.contact_node_dofs(elements.node[p]));
  c.normal = elements.normal;
  c.setting = {elements.law, elements.weight};
  return c;
}

Eigen::VectorXd VelocityScheme::normal_origin(int, const VelocityContact& contact) const {
  return Eigen::VectorXd::Zero(contact.size());
}

LinearContactMarch::LinearContactMarch(VelocityScheme& scheme, const VelocityContact* contact,
                                       const ContactSolverParameters& parameters,
                                       const std::string& backend, StepSolver solver)
    : scheme_(scheme), contact_(contact != nullptr && contact->size() > 0 ? contact : nullptr),
      solver_(std::move(solver)) {
  const Eigen::SparseMatrix<double>& S = scheme_.step_matrix();
  SIG_VERIFY(S.rows() == S.cols() && S.rows() > 0,
             "march: a step matrix of " << S.rows() << " x " << S.cols());
  w_ = Eigen::VectorXd::Zero(S.rows());
  const Stopwatch clock;
  if (contact_ == nullptr) {
    factor_ = make_linear_solver(backend, MatrixKind::spd);
    factor_->factorize(S);
    seconds_factorize_ = clock.seconds();
    return;
  }
  const VelocityContact& c = *contact_;
  SIG_VERIFY(static_cast<int>(c.normal.size()) == c.size() && c.setting.size() == c.size(),
             "march: " << c.size() << " contact nodes with " << c.normal.size() << " normals and "
                       << c.setting.size() << " laws");
  method_ = make_contact_method(parameters);
  options_ = newton_options(parameters, c.setting.law);
  condensation_ =
      std::make_unique<ContactCondensation>(S, c.dofs, c.normal, c.setting.has_friction(), backend,
                                            true); // S is positive definite
  Eigen::VectorXd default_stiffness(c.size());
  for (int p = 0; p < c.size(); ++p)
    default_stiffness[p] = off_wall_stiffness(*method_, c.setting.law[p], c.setting.weight[p]);
  bulk_ = std::make_unique<CondensedBulk>(condensation_->problem(w_), default_stiffness);
  seconds_factorize_ = clock.seconds();
}

LinearContactMarch::~LinearContactMarch() = default;

int LinearContactMarch::dense_factorizations() const {
  return bulk_ ? bulk_->factorizations() : 0;
}

int LinearContactMarch::tail_factorizations() const {
  return bulk_ ? bulk_->tail_factorizations() : 0;
}

VelocityStep LinearContactMarch::step() {
  const Stopwatch clock;
  VelocityStep s;
  s.step = done_ + 1;
  s.time = s.step * scheme_.time_step();
  const Eigen::VectorXd b = scheme_.right_side(s.step);
  s.seconds_right_side = clock.seconds();
  Eigen::VectorXd w;
  if (contact_ == nullptr) {
    w = factor_->solve(b);
    s.contact.converged = w.allFinite();
    if (!s.contact.converged) s.contact.failure = "the step's solve is not finite";
  } else {
    const Eigen::VectorXd origin = scheme_.normal_origin(s.step, *contact_);
    bulk_->restart(condensation_->condense(b), origin);
    const Stopwatch contact_clock;
    s.contact = solver_ ? solver_(*bulk_, contact_->setting, iterate_)
                        : solve_contact(*bulk_, contact_->setting, *method_, options_, iterate_);
    s.seconds_contact = contact_clock.seconds();
    s.normal_velocity = bulk_->penetration() + origin;
    s.tangential_velocity = bulk_->slip();
    w = condensation_->expand(bulk_->displacement());
  }
  if (s.contact.converged) {
    scheme_.accept(s.step, w);
    w_ = std::move(w);
    ++done_;
  }
  s.seconds = clock.seconds();
  return s;
}

VelocityHistory march_in_velocity(LinearContactMarch& march, const VelocityScheme& scheme,
                                  int steps, int output_every, const VelocityObserver& observer) {
  SIG_VERIFY(steps >= 0 && output_every >= 1,
             "march: " << steps << " steps, output_every = " << output_every);
  VelocityHistory h;
  h.steps.reserve(static_cast<std::size_t>(steps));
  h.output_step.push_back(march.steps_done());
  h.output_u.push_back(scheme.displacement());
  h.output_w.push_back(march.velocity());
  const Stopwatch clock;
  for (int n = 1; n <= steps; ++n) {
    h.steps.push_back(march.step());
    const VelocityStep& s = h.steps.back();
    if (!s.converged()) {
      std::ostringstream why;
      why << "step " << s.step << " (t = " << s.time << ") did not converge after "
          << s.contact.iterations() << " iterations: " << s.contact.failure;
      h.converged = false;
      h.failure = why.str();
      break;
    }
    if (n % output_every == 0 || n == steps) {
      h.output_step.push_back(s.step);
      h.output_u.push_back(scheme.displacement());
      h.output_w.push_back(march.velocity());
    }
    if (observer) observer(s);
  }
  // A march stopped early keeps its last good state.
  if (!h.converged && h.output_step.back() != march.steps_done()) {
    h.output_step.push_back(march.steps_done());
    h.output_u.push_back(scheme.displacement());
    h.output_w.push_back(march.velocity());
  }
  h.seconds = clock.seconds();
  return h;
}

} // namespace sig
