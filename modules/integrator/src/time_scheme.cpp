#include "integrator/time_scheme.hpp"

#include "core/error.hpp"
#include "integrator/midpoint.hpp"
#include "integrator/newmark.hpp"
#include "solver/linear_solver.hpp"
#include "solver/mpi_session.hpp"
#include "solver/mumps_solver.hpp"

#include <utility>

namespace sig {

TimeScheme::TimeScheme(Elastodynamics problem, double k, const std::string& linear_solver)
    : problem_(std::move(problem)), k_(k), linear_solver_(linear_solver) {
  const int n = problem_.num_dofs();
  SIG_VERIFY(k_ > 0, "time step k = " << k_ << " must be positive");
  SIG_VERIFY(problem_.K.rows() == n && problem_.K.cols() == n && problem_.M.rows() == n &&
                 problem_.M.cols() == n,
             "K is " << problem_.K.rows() << " x " << problem_.K.cols() << ", M is "
                     << problem_.M.rows() << " x " << problem_.M.cols()
                     << ": both must be square and of the same size");
  // Stored zeros carry nothing (the consistent mass on the stiffness's pattern, the EMM's rows
  // of Gamma3, a rank's lumped mass off its rows): without them a product with M costs less and
  // a rank's step operator has only its rows, its node blocks whole (solver/nodal_frames.hpp).
  problem_.M.prune(0.0);
  S_ = problem_.K + (4.0 / (k_ * k_)) * problem_.M;
  // The backend's name is checked here, before any step: an unknown one lists the choices.
  backend_traits(linear_solver_);
  SIG_VERIFY(!problem_.rank_rows || linear_solver_ == "mumps",
             "the step operator of rank rows is factorized by MUMPS over the ranks, not by "
                 << linear_solver_);
}

TimeScheme::~TimeScheme() = default;

// Solving for the increment d rather than for u_{n+1} keeps the right side free of the large
// (4 / k^2) M u_n term, whose rounding, once differenced into v_{n+1} = (2 / k) d - v_n, grows
// with the distance the body has travelled.
DynamicState TimeScheme::advance(const DynamicState& state, const Eigen::VectorXd& f_bar) const {
  return after_increment(state, solve_step_operator(step_right_side(products(state), f_bar)));
}

TimeScheme::StateProducts TimeScheme::products(const DynamicState& state) const {
  check_state(state);
  return {product(problem_.K, state.u), product(problem_.M, state.v)};
}

Eigen::VectorXd TimeScheme::step_right_side(const StateProducts& state,
                                            const Eigen::VectorXd& f_bar) const {
  return 2.0 * f_bar - 2.0 * state.Ku + (4.0 / time_step()) * state.Mv;
}

DynamicState TimeScheme::after_increment(const DynamicState& state,
                                         const Eigen::VectorXd& d) const {
  const double k = time_step();
  DynamicState next;
  next.time = state.time + k;
  next.u = state.u + d;
  next.v = (2.0 / k) * d - state.v;
  return next;
}

EnergyRecord TimeScheme::energy(const DynamicState& state, const StateProducts& products) const {
  EnergyRecord r;
  r.kinetic = 0.5 * state.v.dot(products.Mv);
  r.elastic = 0.5 * state.u.dot(products.Ku);
  r.total = r.kinetic + r.elastic;
  return r;
}

Eigen::VectorXd TimeScheme::product(const Eigen::SparseMatrix<double>& A,
                                    const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = A * x;
  if (problem_.rank_rows) mpi::sum(y.data(), static_cast<int>(y.size())); // each rank's rows
  return y;
}

void TimeScheme::factorize() const {
  if (solver_) return;
  solver_ = make_linear_solver(linear_solver_, MatrixKind::spd, problem_.rank_rows);
  solver_->factorize(S_);
}

Eigen::VectorXd TimeScheme::solve_step_operator(const Eigen::VectorXd& b) const {
  factorize();
  return solver_->solve(b);
}

std::string TimeScheme::ordering() const {
  const auto* mumps = dynamic_cast<const MumpsSolver*>(solver_.get());
  return mumps != nullptr ? mumps->ordering() : std::string();
}

void TimeScheme::check_state(const DynamicState& state) const {
  SIG_VERIFY(state.u.size() == problem_.num_dofs() && state.v.size() == problem_.num_dofs(),
             name() << " step: state with " << state.u.size() << " displacements and "
                    << state.v.size() << " velocities for " << problem_.num_dofs() << " dofs");
}

namespace {

/// A scheme of the TIME card: its traits and, for elastodynamics, its constructor.
struct SchemeEntry {
  const char* name;
  TimeSchemeTraits traits;
  /// Null for the schemes of a march in velocity (built by their stages).
  std::unique_ptr<TimeScheme> (*make)(Elastodynamics, double, const std::string&);
};

template <class Scheme>
std::unique_ptr<TimeScheme> construct(Elastodynamics problem, double k,
                                      const std::string& linear_solver) {
  return std::make_unique<Scheme>(std::move(problem), k, linear_solver);
}

/// The scheme called `name`: the one place a scheme's name is read.
const SchemeEntry& scheme_named(const std::string& name) {
  static const SchemeEntry entries[] = {
      {"midpoint", {.large_deformation = true}, construct<ImplicitMidpoint>},
      {"newmark", {}, construct<NewmarkAverageAcceleration>},
      {"quasistatic", {.march = MarchKind::quasistatic}, nullptr},
      {"backward-euler", {.march = MarchKind::viscoelastodynamics}, nullptr}};
  for (const SchemeEntry& entry : entries)
    if (name == entry.name) return entry;
  SIG_VERIFY(false, "unknown time scheme '" << name << "' (choose " << time_scheme_names << ")");
  return entries[0];
}

} // namespace

TimeSchemeTraits time_scheme_traits(const std::string& name) {
  return scheme_named(name).traits;
}

std::unique_ptr<TimeScheme> make_time_scheme(const std::string& name, Elastodynamics problem,
                                             double k, const std::string& linear_solver) {
  const SchemeEntry& scheme = scheme_named(name);
  SIG_VERIFY(scheme.make != nullptr, "time scheme '" << name
                                                     << "' is a march in velocity, not a scheme "
                                                        "of elastodynamics (midpoint|newmark)");
  return scheme.make(std::move(problem), k, linear_solver);
}

} // namespace sig
