#pragma once
// One-step implicit schemes for M a + K u = f(t) (integrator/elastodynamics.hpp). Both schemes
// here are second order, unconditionally stable and, for a linear problem, conserve the discrete
// energy 1/2 v.M v + 1/2 u.K u up to the work of the load (8.33); they only differ in how the
// load is sampled over a step. Their step operator is the same matrix
//     S = K + (4 / k^2) M,
// symmetric positive definite whenever M is positive definite on the kernel of K (a free body
// with a consistent, lumped or EMM mass included), factorized once, at the first solve (or by
// the contact condensation of integrator/dynamic_contact.hpp in its frames instead), and reused
// at every step: a step costs one forward/back substitution.
//
// Under mpirun (Elastodynamics::rank_rows) K and M hold only this rank's rows: the products of
// a step's right side and of the energies are summed over the ranks, and MUMPS factorizes S over
// them; states and loads are whole on every rank.
#include "integrator/elastodynamics.hpp"
#include "integrator/energy.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace sig {

class LinearSolver;

/// The state on the free dofs at one time.
struct DynamicState {
  double time = 0.0;
  Eigen::VectorXd u; ///< displacement
  Eigen::VectorXd v; ///< velocity
};

class TimeScheme {
public:
  /// S = K + (4 / k^2) M, to be factorized with `linear_solver` (cholmod|umfpack|mumps, as spd;
  /// mumps over the ranks where the problem holds rank rows).
  TimeScheme(Elastodynamics problem, double k, const std::string& linear_solver);
  virtual ~TimeScheme();
  TimeScheme(const TimeScheme&) = delete;
  TimeScheme& operator=(const TimeScheme&) = delete;

  /// The state at state.time + k.
  DynamicState advance(const DynamicState& state) const {
    return advance(state, step_load(state.time));
  }
  /// The same with the step load f_bar = step_load(state.time) already evaluated. Both schemes
  /// here solve, for the increment d = u_{n+1} - u_n,
  ///     (K + (4 / k^2) M) d = 2 f_bar - 2 K u_n + (4 / k) M v_n,  v_{n+1} = (2 / k) d - v_n
  /// (derivations in midpoint.cpp and newmark.cpp); they differ only in f_bar.
  DynamicState advance(const DynamicState& state, const Eigen::VectorXd& f_bar) const;
  /// K u and M v of a state, summed over the ranks: what its energy and the right side of the
  /// step from it read (a march forms them once a step).
  struct StateProducts {
    Eigen::VectorXd Ku, Mv;
  };
  StateProducts products(const DynamicState& state) const;
  /// The right side 2 f_bar - 2 K u_n + (4 / k) M v_n of the increment's equation (whole, on
  /// every rank), from the products of the state.
  Eigen::VectorXd step_right_side(const StateProducts& state, const Eigen::VectorXd& f_bar) const;
  /// The state at state.time + k of the increment d: u_n + d, (2 / k) d - v_n.
  DynamicState after_increment(const DynamicState& state, const Eigen::VectorXd& d) const;
  /// 1/2 v.M v + 1/2 u.K u of a state and its products (energy.hpp's energy_of, the products
  /// summed over the ranks).
  EnergyRecord energy(const DynamicState& state, const StateProducts& products) const;
  EnergyRecord energy(const DynamicState& state) const { return energy(state, products(state)); }
  /// The load f_bar the scheme applies over [t, t + k]: the discrete energy changes by
  /// f_bar . (u_{n+1} - u_n) over the step (the work of the external forces).
  virtual Eigen::VectorXd step_load(double t) const = 0;
  virtual std::string name() const = 0;

  const Elastodynamics& problem() const { return problem_; }
  double time_step() const { return k_; }

  /// S = K + (4 / k^2) M (this rank's rows under mpirun); the contact strategies condense it
  /// onto the contact nodes (integrator/dynamic_contact.hpp).
  const Eigen::SparseMatrix<double>& step_operator() const { return S_; }
  /// S^{-1} b, S factorized at the first call (sig::Error if it cannot be).
  Eigen::VectorXd solve_step_operator(const Eigen::VectorXd& b) const;
  /// Factorizes S now, if not done yet.
  void factorize() const;
  /// cholmod | umfpack | mumps.
  const std::string& linear_solver() const { return linear_solver_; }
  /// K and M hold this rank's rows of an mpirun job (Elastodynamics::rank_rows).
  bool rank_rows() const { return problem_.rank_rows; }
  /// MUMPS's ordering of S once factorized by the scheme (empty with another backend).
  std::string ordering() const;

protected:
  /// sig::Error unless u and v have the size of the problem.
  void check_state(const DynamicState& state) const;

private:
  /// A x for K or M, summed over the ranks where they hold rank rows.
  Eigen::VectorXd product(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x) const;

  Elastodynamics problem_;
  double k_;
  std::string linear_solver_;
  Eigen::SparseMatrix<double> S_;
  mutable std::unique_ptr<LinearSolver> solver_; ///< S's factorization, made at the first solve
};

/// Card field `TIME scheme=`: the schemes of elastodynamics above and of the marches in velocity.
inline constexpr const char* time_scheme_names = "midpoint|newmark|quasistatic|backward-euler";

/// The march that steps a TIME scheme.
enum class MarchKind {
  elastodynamics,     ///< midpoint, newmark: a TimeScheme (above) on M a + K u = f
  quasistatic,        ///< ch. 5, no inertia: the march in velocity of kelvin_voigt_scheme.hpp
  viscoelastodynamics ///< ch. 6: the march in velocity of backward_euler_scheme.hpp
};

/// What a stage must know of a TIME scheme before it builds its march.
struct TimeSchemeTraits {
  MarchKind march = MarchKind::elastodynamics;
  /// A hyperelastic body may march with it (large deformation: the midpoint rule only).
  bool large_deformation = false;
};

/// The traits of the scheme called `name` (time_scheme_names); sig::Error listing the choices
/// for an unknown name.
TimeSchemeTraits time_scheme_traits(const std::string& name);

/// The scheme of elastodynamics called `name` (midpoint or newmark); sig::Error listing the
/// choices for an unknown name or a scheme of a march in velocity.
std::unique_ptr<TimeScheme> make_time_scheme(const std::string& name, Elastodynamics problem,
                                             double k,
                                             const std::string& linear_solver = "cholmod");

} // namespace sig
