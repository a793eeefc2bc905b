#pragma once
// One-step implicit schemes for M a + K u = f(t) (integrator/elastodynamics.hpp). Both schemes
// here are second order, unconditionally stable and, for a linear problem, conserve the discrete
// energy 1/2 v.M v + 1/2 u.K u up to the work of the load (8.33); they only differ in how the
// load is sampled over a step. Their step operator is the same matrix
//     S = K + (4 / k^2) M,
// symmetric positive definite whenever M is positive definite on the kernel of K (a free body
// with a consistent, lumped or EMM mass included), factorized once at construction and reused
// at every step: a step costs one forward/back substitution.
#include "integrator/elastodynamics.hpp"

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
  /// Factorizes S = K + (4 / k^2) M with `linear_solver` (cholmod|umfpack|mumps, as spd).
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
  /// The load f_bar the scheme applies over [t, t + k]: the discrete energy changes by
  /// f_bar . (u_{n+1} - u_n) over the step (the work of the external forces).
  virtual Eigen::VectorXd step_load(double t) const = 0;
  virtual std::string name() const = 0;

  const Elastodynamics& problem() const { return problem_; }
  double time_step() const { return k_; }

  /// S^{-1} b with the factorization of S = K + (4 / k^2) M (the contact strategies condense S
  /// onto the contact nodes with it, integrator/dynamic_contact.hpp).
  Eigen::VectorXd solve_step_operator(const Eigen::VectorXd& b) const;
  /// S^{-1} B, column by column.
  Eigen::MatrixXd solve_step_operator(const Eigen::MatrixXd& B) const;

protected:
  /// sig::Error unless u and v have the size of the problem.
  void check_state(const DynamicState& state) const;

private:
  Elastodynamics problem_;
  double k_;
  std::unique_ptr<LinearSolver> solver_;
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
