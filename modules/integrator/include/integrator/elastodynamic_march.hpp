#pragma once
// The scheme hook (integrator/march.hpp) of linear elastodynamics, M a + K u = f, stepped by a
// TimeScheme (midpoint, Newmark), without or with node-to-rigid contact. With contact each step
// is the scheme's step plus the end-of-step contact forces of a strategy
// (integrator/contact_strategy.hpp), on the condensed problem of integrator/dynamic_contact.hpp:
//   1. the free step on the components x = G u of the p contact nodes, their normal
//      displacements and, when a law has friction, their slips: the right side
//      2 f_bar - 2 K u_n + (4 / k) M v_n condensed onto them (the forward half of a sparse
//      solve with S factorized once, the components its Schur complement S_c);
//   2. the strategy's forces lambda on that condensed step (a CondensedBulk of the one contact
//      driver, p or d p unknowns), from x_n and the free step;
//   3. the components' increment from lambda, exactly, and the whole body's increment d with
//      them (the backward half), v_{n+1} = (2 / k) d - v_n.
// Free flight: when the strategy's first laws give no force at the free step's end and the free
// step is in equilibrium to the strategy's eps, the strategy's first test
// (contact_strategy.hpp, predictor_solves_step) returns the free step as the step, no Newton
// iteration, no force: such a step costs the split solve (the two halves around S_c^{-1} g:
// one forward-backward substitution), the bulk's restart (a product with A) and that test. The
// plain factorization of S, whose solve is some 15 % cheaper than the split one on the 3D ball,
// is not made: it costs about 30 of its solves (datafiles/scene3d/README.md, *Performance*).
// Under mpirun the scheme holds this rank's rows of K and M (Elastodynamics::rank_rows): MUMPS
// factorizes S over the ranks, its complement on rank 0 sent to every rank, and every rank runs
// the same steps on the whole vectors.
// Friction is that of the hyperelastic march (stages/finite_strain_march.hpp, ALGORITHMS.md 4.3):
// each strategy's phases carry the CONT friction law (Tresca, Coulomb with the whole normal
// force, mu1 / mu2 of the penetration), the slip of a node over a step being the increment of
// its tangential displacement, t . (u_{n+1} - u_n); in 3D the slip is the vector of the node's
// tangent plane (t1, t2 . (u_{n+1} - u_n)) and the force lies in the disc of radius the bound
// (the Coulomb cone's section), one code for d = 2 and 3. Where a linear body differs: the frame
// (n, t) of a node is the obstacle's at the node's reference position, as the penetration
// B u - d is linear in u (small displacements; on a plane the same as the hyperelastic march's
// current frame), and the balance E + interface - friction work - wall work = E0 holds to
// round-off whatever the Newton tolerance, the state being the exact linear response to the
// forces found (for a hyperelastic body it holds to the Newton tolerance).
// Per step the record holds the energy (8.33), the work of the load and of the contact forces
// over the step (which the march loop sums and splits as energy.hpp says), the maximal
// penetration [x_{n+1} - d]_+, the nodes with N > 0, the forces and statuses per node and the
// strategy's iterations (1, the linear solve, without contact).
#include "integrator/contact_strategy.hpp"
#include "integrator/dynamic_contact.hpp"
#include "integrator/march.hpp"
#include "integrator/time_scheme.hpp"

#include <memory>
#include <optional>
#include <string>

namespace sig {

class CondensedBulk;

class ElastodynamicSteps final : public MarchScheme {
public:
  /// Without contact, from `initial` (free dofs).
  ElastodynamicSteps(const TimeScheme& scheme, DynamicState initial);
  /// With the contact of `boundary` and the forces of `strategy` (both must outlive the hook):
  /// the step operator condensed onto the contact nodes once. sig::Error for inconsistent
  /// input.
  ElastodynamicSteps(const TimeScheme& scheme, const ContactBoundary& boundary,
                     const ContactStrategy& strategy, DynamicState initial);
  ~ElastodynamicSteps() override;

  MarchRecords records() const override { return {.energy = true, .balance = true}; }
  StepRecord start() const override;
  StepRecord step(int n) override;
  DynamicState state() const override { return state_; }
  /// MUMPS's ordering of the step operator (empty with another backend).
  std::string ordering() const;

private:
  const TimeScheme& scheme_;
  const ContactBoundary* boundary_ = nullptr;
  const ContactStrategy* strategy_ = nullptr;
  std::optional<CondensedContact> condensed_; ///< with contact
  std::vector<int> normal_dof_;               ///< 0 .. p - 1: the normal displacements
  /// p .. d p - 1 with friction: the slips, d - 1 a node (3D: along t1, t2, node i's at p + 2 i)
  std::vector<int> tangential_dof_;
  DynamicState state_;
  TimeScheme::StateProducts products_; ///< of state_: its energy, the next step's right side
  Eigen::VectorXd x_now_;              ///< the condensed components of the state (G u)
  Eigen::VectorXd q_now_;              ///< the penetrations of the state
  /// The contact problem's bulk, made at the first step, restarted at the next.
  std::unique_ptr<CondensedBulk> bulk_;
};

/// Without contact: `steps` steps of `scheme` from `initial`, the work of the loads accumulating
/// step_load(t_n) . (u_{n+1} - u_n) (the march loop of integrator/march.hpp on
/// ElastodynamicSteps).
MarchHistory march(const TimeScheme& scheme, const DynamicState& initial, int steps,
                   int output_every = 0, const StepObserver& observer = {});

/// `steps` steps of `scheme` with the contact of `boundary` and `strategy` (the march loop of
/// integrator/march.hpp on ElastodynamicSteps).
MarchHistory march_with_contact(const TimeScheme& scheme, const ContactBoundary& boundary,
                                const ContactStrategy& strategy, const DynamicState& initial,
                                int steps, int output_every = 0, const StepObserver& observer = {});

} // namespace sig
