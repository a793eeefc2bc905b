#pragma once
// The dynamic contact strategies of ch. 3.3 and 8.4 (ALGORITHMS.md 4.3), one class per file
// (src/*_strategy.cpp). Each is a sequence of Newton phases of the one contact driver
// (solver/contact_newton.hpp) on the bulk of the time step, with per-node laws of the contact
// kernel (contact/contact_kernel.hpp) built from the CONT laws (normal law, wall depth g,
// friction) and the state at the start of the step; the contact conditions hold at t_n, the end
// of the step ((8.26)-(8.28)):
//   signorini          the CONT law (Signorini, wall at g), by PDAS
//   compliance         normal compliance cn = r, no wall (the thesis's "g = 1000"), by PDAS
//   specific-penalty   the compliance cn = r as its secant over the step (3.51)/(8.32), no wall,
//                      by PDAS (its multipliers: the friction's only)
//   two-step           [13], 3.3.3: (a) the CONT law by PDAS; (b) continuing from (a), on the
//                      nodes (a) left in contact the persistency condition -- the normal velocity
//                      at t_n is <= 0 -- and no force on the others
//   ipm                (8.30)-(8.31): (a) the secant compliance alone; (b) continuing from (a)
//                      when a node went beyond g, the secant compliance limited by the wall at
//                      q_n = g on every node (its force there the compliance at g plus the
//                      wall's reaction, choice C14's p_g = p_spe(g, q_{n-1}))
// With a friction law each phase carries it (Coulomb with the whole normal force as the bound,
// or mu1 / mu2 of the penetration (8.3)), the slip being the tangential displacement over the
// step: the velocity of (8.28) times k.
//
// The bulk is the time step's: CondensedBulk for a linear body (elastodynamic_march.hpp: the
// normal displacements and, with friction, the slips), the dynamic FiniteStrainBulk for a
// hyperelastic one (stages/finite_strain_march.hpp), each at the step's predictor when solve() is
// called and at the step's solution after it. A step that does not converge is a result (converged
// = false, failure says why), never an exception.
#include "contact/contact_status.hpp"
#include "integrator/march.hpp"
#include "solver/contact_newton.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace sig {

class ContactBulk;

/// Card field `CONTACT ... strategy=`.
inline constexpr const char* contact_strategy_names =
    "signorini|compliance|specific-penalty|two-step|ipm";

/// What two-step's persistency (b) holds at zero ([choice] C15, ALGORITHMS.md 4.3 (B)).
enum class Persistency {
  /// The midpoint velocity at t_n (3.39), -v_{n-1} + (2 / k)(q_n - q_{n-1}): the wall of (b) sits
  /// at q_{n-1} + k v_{n-1} / 2, so a node arriving at speed v sinks up to k v / 2.
  midpoint,
  /// The increment q_n - q_{n-1} (the backward difference (3.43)): every normal force of (b)
  /// does no work, but a node never moves closer than where it was at t_{n-1}.
  increment
};

struct ContactStrategyParameters {
  /// Stiffness per unit area of the foundation (compliance, specific-penalty, ipm): nodal force
  /// r * weight * penetration; > 0 where used.
  double r = 0;
  /// PDAS's parameter (wall and friction multipliers), > 0. The solution does not depend on
  /// it; the friction's semi-smooth Newton does: of the order of a contact node's stiffness in
  /// the step per unit length converges, far above or below it a slipping node may cycle
  /// between its two directions (Nv). The SOLVER card's default, as in a static solve.
  double gamma = ContactSolverParameters::card_default("gamma");
  int max_iterations = 50; ///< per Newton phase
  double eps = 1e-10;      ///< the driver's test (iv), relative
  Persistency persistency = Persistency::midpoint;
};

/// The contact nodes at the start of the step.
struct ContactStepStart {
  Eigen::VectorXd penetration; ///< q_n at t_{n-1}
  Eigen::VectorXd
      normal_velocity;  ///< dq_n/dt at t_{n-1}: the midpoint velocity towards the obstacle
  double time_step = 0; ///< k
};

struct ContactStepSolution {
  Eigen::VectorXd normal_force;     ///< N per node (nodal force, pushing the body off)
  Eigen::VectorXd tangential_force; ///< T per node (opposing the slip)
  std::vector<NormalStatus> normal_status;
  std::vector<FrictionStatus> friction_status;
  /// The laws of the phase that gave the solution (their compliance_energy is the energy the
  /// foundation stores at the end of the step).
  std::vector<ContactLaw> law;
  bool converged = false;
  std::string failure;
  int iterations = 0; ///< Newton iterations, every phase summed (0: the predictor was the step)
};

class ContactStrategy {
public:
  explicit ContactStrategy(ContactStrategyParameters p) : p_(p) {}
  virtual ~ContactStrategy() = default;
  virtual std::string name() const = 0;
  /// One step on `bulk`, from the CONT laws and weights of `setting` (one per bulk contact node).
  ContactStepSolution solve(ContactBulk& bulk, const ContactSetting& setting,
                            const ContactStepStart& start) const;
  const ContactStrategyParameters& parameters() const { return p_; }

protected:
  /// The laws of the first phase.
  virtual std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                             const ContactStepStart& start) const = 0;
  /// The phases, from the first one's laws: the solution of the step. By default the one phase
  /// of the first laws (two-step and IPM add a second).
  virtual ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                                     const ContactStepStart& start) const;
  /// One Newton phase of PDAS (gamma) on `bulk` with `setting`, continuing from `iterate`; adds
  /// to `solution` (forces, statuses, laws, iterations).
  void phase(ContactBulk& bulk, const ContactSetting& setting, ContactIterate& iterate,
             ContactStepSolution& solution, const std::string& label = "") const;
  /// No force, every node free, under the laws `first` (`slips` tangential forces).
  static ContactStepSolution free_solution(const ContactSetting& first, Eigen::Index slips);

  ContactStrategyParameters p_;
};

/// The strategy called `name` (contact_strategy_names); sig::Error for an unknown name, a
/// non-positive r where the strategy needs it, or other parameters out of range.
std::unique_ptr<ContactStrategy> make_contact_strategy(const std::string& name,
                                                       const ContactStrategyParameters& p);

/// What a card reader must know of a strategy before the strategy is made.
struct ContactStrategyTraits {
  /// A foundation stiffness r > 0 (compliance, specific-penalty, ipm).
  bool needs_r = false;
  /// A wall at the CONT laws' depth g (signorini, two-step; ipm: the allowed penetration); the
  /// compliance and the specific penalty have none.
  bool has_wall = true;
  /// What phase (b) holds at zero is a choice (two-step: ContactStrategyParameters::persistency).
  bool has_persistency = false;
};

/// The traits of the strategy called `name` (as make_contact_strategy); sig::Error for an
/// unknown name.
ContactStrategyTraits contact_strategy_traits(const std::string& name);

/// The bulk's iterate (the step's predictor) already solves the step: the bulk is in
/// equilibrium there to eps and no law gives a force (every node off the obstacle, no secant
/// force from a penetration at the start). Free flight then costs no Newton iteration, and its
/// states stay the scheme's exact ones.
bool predictor_solves_step(const ContactBulk& bulk, const ContactSetting& setting, double eps);

/// The forces and statuses of a step's solution as the march records them.
ContactRecord contact_record(const ContactStepSolution& solution);

/// The energy of the foundation, sum_i w_i compliance_energy(law_i, q_n,i).
double interface_energy(const std::vector<ContactLaw>& laws, const Eigen::VectorXd& weight,
                        const Eigen::VectorXd& penetration);

} // namespace sig
