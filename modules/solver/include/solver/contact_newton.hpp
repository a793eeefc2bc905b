#pragma once
// The one semi-smooth Newton driver of every contact solve (static linear, finite strain, the
// time steps): generalized Newton (3.11) on (u, lambda, t) for the per-node kernel of
// contact/contact_kernel.hpp, with the method (contact_method.hpp) as a policy and the bulk
// (contact_bulk.hpp) behind an interface. Its loop is the thesis's, steps (i)-(iv) of ch. 3/7:
//   (i)   start from the given iterate: the bulk's displacement and `iterate` (warm start);
//   (ii)  per node, the kernel's branches at the iterate: wall active or not, stick or slip;
//   (iii) one linearized step with the matching condition on each node: on the wall q_n = g
//         (Dirichlet, the multiplier its reaction), off it lambda = 0 (or projection's Robin
//         spring), the compliance as a spring, stick q_t = 0, slip t = sigma s (for Coulomb
//         s = mu N, coupled to the normal force); then the step length (below);
//   (iv)  stop when ||x(k+1) - x(k)|| <= eps ||x(k+1)||, ||R(x(k+1))|| <= eps and (but for
//         alm) the branches repeat, x = (u, lambda / w, t / w) with the multipliers as
//         pressures, R = (equilibrium, w C_n, w C_t) relative to the bulk's force scale.
// A solve that does not converge is a result: converged = false, failure and the history.
//
// Globalization (newton_guard.hpp), for every method and bulk, measured on the natural residual
//     ||R|| = ||(equilibrium, w C_n, w C_t)||,
// C_n, C_t the Alart-Curnier functions of contact_kernel.hpp at each node's natural augmentation
// k / w, k the bulk's stiffness of the node's own component (ContactBulk::contact_stiffness):
// every row is then a force, w C = lambda - [lambda + k (q_n - g)]_+ the force that would put the
// node right, and the residual does not depend on the method's parameter (r, gamma, c only steer
// the steps; a merit scaled by them refused at gamma >= 1e4 the full steps whose penetrations the
// next test puts right). The same ||R|| relative to the bulk's force scale is test (iv)'s.
//  - Step length: halving from the full step (alpha = 1, 1/2, ... 2^-12; the first step of a
//    solve with contact nodes, whose branches are the start's, from the longest length the
//    bulk trusts its linearization over, ContactBulk::trusted_length, NEWTON.md item 7), the
//    first length whose
//    residual of the system the step linearized (its branches held) passes Armijo's test against
//    the present iterate's, and whose residual itself stays below a trust ceiling, kRelaxation
//    times the largest merit of the last kMeritWindow iterates (the nonmonotone reference of
//    Grippo, Lampariello and Lucidi: an active-set change may raise the residual for a step, not
//    without bound); if no length passes, the largest admissible one below the ceiling, else the
//    one of least residual. The watchdog (R. M. Chamberlain, M. J. D. Powell, C. Lemarechal,
//    H. C. Pedersen, "The watchdog technique for forcing convergence in algorithms for
//    constrained optimization", Math. Programming Study 16, 1982; Nocedal and Wright,
//    "Numerical Optimization", 2006, 15.6): a relaxed step that passed its test and raised the
//    merit must be repaid, the merit below the one it started from by Armijo's test, within
//    kWatchSteps more steps, or one step more each time the last step's contraction of the merit
//    would repay it within kWatchSteps at that rate (at most kWatchSteps such steps: a cold
//    start's raise on a path converging linearly); else the solve returns to the iterate it
//    started from (the bulk's
//    checkpoint, the multipliers, branches, merit memory, cycle guard, damping and drift as they
//    were) and searches that step again under a ceiling of the present merit. The iterations
//    spent count; restricted steps (below) end a watch. From an
//    iterate at round-off (a residual below kMeritPrecision of the force scale and eps), a trial at
//    round-off passes, relaxed or monotone: merits there cannot be ranked (NEWTON.md item 8). A
//    trial outside the bulk's domain (an inverted element) or with a residual that is not finite is
//    never taken; with full steps only (search=no) it is a divergence.
//  - Unheld steps: where the active, stick and slip sets hold no rigid motion of the body (a body
//    held by contact and friction alone, from rest, or with every node slipping one way), the
//    step exists only through the bulk's proximal term (condensed_bulk.hpp) and its rigid part is
//    the unbalanced load over that term: an unbounded motion. Such a step is cut where a node
//    first comes to hold the body (its wall becomes active, its compliance engages or it enters
//    stick), the ratio test of a primal active-set method; without any, the load is not held
//    and the solve stops with `drift`.
//  - Cycles and stalls: a branch set that repeats without progress restricts the steps: a linear
//    complementarity problem (frictionless Signorini on a linear bulk, a P-matrix) changes one
//    branch per iteration with full steps (Murty's least-index rule, finite there), the others
//    take monotone steps (the least residual over the halvings and the residual's breakpoints
//    along the step); a second cycle, or a monotone step that cannot lower the residual four
//    times in a row, adds the other restriction; past both, `cycling` or `stagnation`. Ten
//    iterations without a new least residual also make the steps monotone.
//  - The slip test's augmentation: the tangential test (ii) of a method with multipliers
//    augments the slip by min(r, k_t / w), k_t the node's natural stiffness [choice]. Its trial
//    traction t + r q_t predicts the traction of a node held in place; a bulk resists a slip with
//    about k_t, so an r far above it declares slipping every node whose slip the bulk's own
//    elasticity would absorb (at r = 30 k the frictional Hertz deck kept every node slipping and
//    drifted, 1 of 15 nodes entering stick per unheld cut), while below it the test is the
//    thesis's. The solution does not depend on r_t; the wall's test keeps r.
// One code for d = 2 and 3 (a template on d, the 3D driver where the bulk has two tangential
// unknowns per node): in 3D the slip and the tangential multiplier of a node are vectors of its
// tangent plane, the stick test |t + r q_t| <= s the cone's, and a slipping node's step the
// linearized projection on the disc (contact_newton.cpp, tangential_conditions_3d).
// A solve that does not converge is a result: converged = false, the reason (NewtonFailure),
// the failure's text and the history.
#include "contact/contact_kernel.hpp"
#include "contact/contact_law.hpp"
#include "contact/contact_status.hpp"
#include "solver/contact_bulk.hpp"
#include "solver/contact_method.hpp"
#include "solver/newton_guard.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace sig {

/// What the driver knows of the contact elements: their laws and nodal weights (no mesh).
struct ContactSetting {
  std::vector<ContactLaw> law;
  Eigen::VectorXd weight; ///< w > 0: nodal force = pressure x w
  int size() const { return static_cast<int>(law.size()); }
  bool has_friction() const;
};

/// The branch of the kernel a node's linear step used (step (ii)).
using NodeBranch = KernelBranch;

/// The multiplier part of the Newton vector, nodal forces (pressure x weight), and the branches
/// of the last iteration: a warm start in, the solution out. Empty vectors start from zero.
struct ContactIterate {
  Eigen::VectorXd lambda; ///< wall multipliers
  /// tangential multipliers, d - 1 per node (flat as contact_bulk.hpp's tangential vectors)
  Eigen::VectorXd t;
  /// In 3D the branch as a set (wall, stick, slipping or not: slip 1 or 0): the direction of a
  /// slip turns continuously, the sets repeat.
  std::vector<NodeBranch> branch;
};

struct IterationRecord {
  int active = 0;  ///< nodes on the wall in the iteration's step
  int entered = 0; ///< of them, nodes off the wall in the previous iteration (a cold start: all)
  int left = 0;    ///< nodes on the wall in the previous iteration, off it now
  int stick = 0;   ///< nodes sticking
  int slip = 0;    ///< nodes slipping with a friction bound s > 0
  double residual = 0;  ///< relative residual after the iteration
  double increment = 0; ///< relative increment ||x(k+1) - x(k)|| / ||x(k+1)||
  double step = 0;      ///< E_k = ||x(k+1) - x(k)||, the measure of the thesis's Figs 7.14-7.16
  /// How the step was taken (header): 0 full or searched (relaxed), 1 an unheld step cut where a
  /// node first holds the body, 2 monotone, 3 one branch change (after a cycle), 4 an escape: no
  /// length lowered the search's merit, the least (or the largest trusted) was taken, 5 the step
  /// from a watchdog's return (header), searched under a ceiling of the present merit
  std::int8_t kind = 0;
  /// The search's merit after the step over before it: the residual of the system the step
  /// linearized (relaxed, one change) or the residual itself (monotone); < 1 but for escapes
  /// (0 for an unheld step's cut, which has no merit to lower)
  double merit_ratio = 0;
  /// Per contact node, 1 if on the wall in the iteration's step: the active set itself, to see
  /// where it moves (a contact patch travelling one node per iteration, scene 7b).
  std::vector<std::int8_t> wall;
};

/// The defaults are the SOLVER card's (ContactSolverParameters): a driver given no options stops
/// as a deck without a SOLVER card does.
struct ContactNewtonOptions {
  double eps = ContactSolverParameters::solve_eps;
  int max_iterations = ContactSolverParameters::solve_max_iterations;
  /// False: full Newton steps whatever their residual, the methods as the thesis states them
  /// (SOLVER search=no, for studies); true: the globalization of the header.
  bool globalize = true;
};

/// The options of `parameters`.
ContactNewtonOptions newton_options(const ContactSolverParameters& parameters);

struct ContactNewtonResult {
  bool converged = false;
  NewtonFailure reason = NewtonFailure::none; ///< why it stopped without converging
  std::string failure;                        ///< the reason's name and its details
  double drift = 0; ///< reason drift: the length of the unbounded step that showed it
  std::vector<IterationRecord> history;
  std::vector<double> step_length;  ///< line-search alpha per iteration (1 for linear bulks)
  Eigen::VectorXd normal_force;     ///< N per node at the end (nodal force, >= 0 at a solution)
  Eigen::VectorXd tangential_force; ///< T per node, d - 1 components each (flat)
  std::vector<NormalStatus> normal_status;     ///< of the last iteration's branches
  std::vector<FrictionStatus> friction_status; ///< of the last iteration's branches
  int iterations() const { return static_cast<int>(history.size()); }
};

/// Newton from the bulk's iterate and `iterate`, which end at the last iterate. sig::Error for
/// inconsistent sizes; non-convergence is returned.
ContactNewtonResult solve_contact(ContactBulk& bulk, const ContactSetting& setting,
                                  const ContactMethod& method, const ContactNewtonOptions& options,
                                  ContactIterate& iterate);

} // namespace sig
