// The march in velocity on a linear bulk (linear_contact_march.hpp).
#include "integrator/linear_contact_march.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/condensed_bulk.hpp"
#include "solver/contact_condensation.hpp"
#include "solver/linear_solver.hpp"
#include "solver/mpi_session.hpp"
#include "solver/mumps_solver.hpp"

#include <sstream>

namespace sig {

Eigen::VectorXd VelocityScheme::normal_origin(int, const VelocityContact& contact) const {
  return Eigen::VectorXd::Zero(contact.size());
}

EnergyRecord VelocityScheme::energy(const VelocityContact*) const {
  return {};
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
    factor_ = make_linear_solver(backend, MatrixKind::spd, scheme_.rank_rows());
    factor_->factorize(S);
    seconds_factorize_ = clock.seconds();
    return;
  }
  const VelocityContact& c = *contact_;
  SIG_VERIFY(static_cast<int>(c.normal.size()) == c.size() && c.setting.size() == c.size(),
             "march: " << c.size() << " contact nodes with " << c.normal.size() << " normals and "
                       << c.setting.size() << " laws");
  method_ = make_contact_method(parameters);
  options_ = newton_options(parameters);
  std::vector<ContactFrame> frames;
  for (const Eigen::VectorXd& n : c.normal)
    frames.push_back(contact_frame(n)); // nodal_frame(n) in 2D
  condensation_ = std::make_unique<ContactCondensation>(S, c.first_dof, std::move(frames),
                                                        c.setting.has_friction(), backend,
                                                        true, // S is positive definite
                                                        scheme_.rank_rows());
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

std::string LinearContactMarch::ordering() const {
  if (condensation_) return condensation_->ordering();
  const auto* mumps = dynamic_cast<const MumpsSolver*>(factor_.get());
  return mumps != nullptr ? mumps->ordering() : std::string();
}

int LinearContactMarch::ranks() const {
  return scheme_.rank_rows() ? mpi::size() : 1;
}

MarchRecords LinearContactMarch::records() const {
  return {.energy = scheme_.has_energy(), .contact_per_step = true};
}

StepRecord LinearContactMarch::start() const {
  StepRecord r;
  r.step = done_;
  r.time = done_ * scheme_.time_step();
  if (scheme_.has_energy()) r.energy = scheme_.energy(contact_);
  if (contact_ != nullptr) {
    const int m = contact_->size();
    // The layout of the steps' tangential values (solver/contact_bulk.hpp): d - 1 a node with
    // friction, one without.
    const int tangents = bulk_->has_tangential() ? bulk_->tangents() : 1;
    ContactRecord& c = r.contact;
    c.normal_force = c.normal_velocity = Eigen::VectorXd::Zero(m);
    c.tangential_force = c.tangential_velocity = Eigen::VectorXd::Zero(tangents * m);
    c.normal_status.assign(m, NormalStatus::free);
    c.friction_status.assign(m, FrictionStatus::none);
  }
  return r;
}

DynamicState LinearContactMarch::state() const {
  return {done_ * scheme_.time_step(), scheme_.displacement(), w_};
}

StepRecord LinearContactMarch::step(int n) {
  SIG_VERIFY(n == done_ + 1, "march: step " << n << " after step " << done_);
  const Stopwatch clock;
  StepRecord s;
  s.time = n * scheme_.time_step();
  const Eigen::VectorXd b = scheme_.right_side(n);
  s.seconds.right_side = clock.seconds();
  Eigen::VectorXd w;
  if (contact_ == nullptr) {
    w = factor_->solve(b);
    s.iterations = 0;
    s.converged = w.allFinite();
    if (!s.converged) s.failure = "the step's solve is not finite";
  } else {
    const Eigen::VectorXd origin = scheme_.normal_origin(n, *contact_);
    bulk_->restart(condensation_->condense(b), origin);
    const Stopwatch contact_clock;
    ContactNewtonResult result =
        solver_ ? solver_(*bulk_, contact_->setting, iterate_)
                : solve_contact(*bulk_, contact_->setting, *method_, options_, iterate_);
    s.seconds.contact = contact_clock.seconds();
    s.iterations = result.iterations();
    s.converged = result.converged;
    if (!s.converged) {
      std::ostringstream why;
      why << "the contact solve did not converge after " << result.iterations()
          << " iterations: " << result.failure;
      s.failure = why.str();
    }
    s.contact = {std::move(result.normal_force),  std::move(result.tangential_force),
                 std::move(result.normal_status), std::move(result.friction_status),
                 bulk_->penetration() + origin,   bulk_->slip()};
    w = condensation_->expand(bulk_->displacement());
  }
  if (s.converged) {
    scheme_.accept(n, w);
    w_ = std::move(w);
    ++done_;
    if (scheme_.has_energy()) s.energy = scheme_.energy(contact_);
  }
  return s;
}

} // namespace sig
