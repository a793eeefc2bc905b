#pragma once
// Hyperelastic dynamics (thesis ch. 8, Scene 8b): the implicit midpoint rule (3.39) for a body in
// large deformation, with the stress of TIME stress= (Gonzalez's (3.41), energy-consistent, or the
// plain midpoint configuration's), each step solved by the one contact Newton driver
// (solver/contact_newton.hpp) on the dynamic FiniteStrainBulk (stages/finite_strain_bulk.hpp):
//     (2 / k^2) M (u_n - u_{n-1} - k v_{n-1}) + G(u_n; u_{n-1}) - f + contact forces at t_n = 0,
//     v_n = (2 / k)(u_n - u_{n-1}) - v_{n-1},
// from the predictor u_{n-1} + k v_{n-1}, with the phases of a contact strategy
// (integrator/contact_strategy.hpp) when the body has contact elements: the contact and friction
// conditions hold at t_n ((8.26)-(8.28)), at the current position of the contact nodes (the
// penetration -d(X + u) of the obstacle's signed distance d). A step whose predictor already
// solves it (free flight: no force anywhere, the bulk in equilibrium to the driver's tolerance)
// takes it as the step, with no Newton iteration: a rigid translation is then exact.
//
// The energy record of each step (energy.hpp): kinetic 1/2 v.M v, elastic sum_T |T| t W(F), the
// work of the constant load, and the contact's work split into the foundation's stored energy,
// the friction's work (-sum T slip over the step) and the wall's, so that
//     E_n - E_{n-1} = f . (u_n - u_{n-1}) - sum N (q_n - q_{n-1}) - sum T slip
// (Prop. 8.1, (8.34)), exact to the Newton tolerance with Gonzalez's stress. States are on the
// mesh's full dofs (Dirichlet values held, their velocity zero).
#include "integrator/march.hpp"
#include "solver/contact_newton.hpp"
#include "stages/finite_strain_bulk.hpp"

#include <string>

namespace sig {

class ContactStrategy;

struct HyperelasticMarchOptions {
  std::string backend = "mumps"; ///< umfpack | mumps (an LU: Gonzalez's tangent is not symmetric)
  double eps = 1e-10;            ///< test (iv) of a step without contact elements
  int max_iterations = 50;       ///< Newton iterations of such a step
};

/// The scheme hook of the march loop (integrator/march.hpp) for a hyperelastic body (header).
class HyperelasticSteps final : public MarchScheme {
public:
  /// `problem` (with its mass, k and stress; it must outlive the hook) from `initial` (full
  /// dofs); `strategy` is required when the problem has contact elements and ignored otherwise.
  /// sig::Error for inconsistent input.
  HyperelasticSteps(const FiniteStrainProblem& problem, const ContactStrategy* strategy,
                    const HyperelasticMarchOptions& options, const DynamicState& initial);

  MarchRecords records() const override { return {.energy = true, .balance = true}; }
  StepRecord start() const override;
  StepRecord step(int n) override;
  DynamicState state() const override { return state_; }

private:
  /// The energies of `state` whose strain energy is `elastic`.
  EnergyRecord energies(const DynamicState& state, double elastic) const;

  const FiniteStrainProblem& problem_;
  const ContactStrategy* strategy_;
  HyperelasticMarchOptions options_;
  int m_; ///< contact nodes
  ContactSetting setting_;
  FiniteStrainBulk bulk_;
  DynamicState state_;
  Eigen::VectorXd load_;
  Eigen::VectorXd q_now_, v_n_; ///< penetrations and normal velocities of the contact nodes
};

/// `steps` steps of HyperelasticSteps(problem, strategy, options, initial). A step that fails
/// stops the march (history.converged = false, failure naming the step).
MarchHistory march_hyperelastic(const FiniteStrainProblem& problem, const ContactStrategy* strategy,
                                const HyperelasticMarchOptions& options,
                                const DynamicState& initial, int steps, int output_every = 0,
                                const StepObserver& observer = {});

} // namespace sig
