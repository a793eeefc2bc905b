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
// Step length: alpha = 1, 1/2, ... 2^-12 of the step (u and the multipliers), the first that lowers
// the search's merit; a trial outside the bulk's domain (an inverted element) or with a residual
// that is not finite is never taken.
//  - A nonlinear bulk always searches, on the residual of the system (iii) linearized: ||R|| with
//    the branches of (ii) held (the kernel's smooth piece, contact_kernel.hpp) and, off the wall,
//    the method's condition there (lambda = 0, or projection's Robin law). The step is the exact
//    Newton step of that smooth system, so a short enough step lowers it, and the search acts on
//    the bulk's nonlinearity alone while the active set is (ii)'s business, as in the thesis's
//    loop. On each trial's own branches instead, a node the step leaves penetrating while off the
//    wall counts r_n times its penetration, and r_n = gamma is the parameter the thesis finds
//    without influence (Table 7.5): at gamma >= 1e4 the search then refused the full steps whose
//    penetrations the next (ii) puts right, and crept on steps of 2^-5 ... 2^-11 (the ring of
//    scene 7b in one load step at N = 256: 81 iterations; 24 for every gamma with the branches
//    held, projection 23). If no alpha lowers the merit, the largest admissible one is taken (an
//    active-set change may raise the residual for one step).
//  - A linear bulk searches when `line_search` says so, while its relative residual is above
//    1e3 eps, on ||R|| at each trial's own branches, and, if no alpha lowers it, takes the one of
//    least ||R||: its search is there to damp the branch changes themselves (held, they would
//    make every full step exact). Friction needs it where the tangential rigid motion of the body
//    is held by friction alone, since a full step that leaves every node slipping holds nothing
//    sideways and drifts by the tangential load over the proximal term of condensed_bulk.hpp, a
//    state the stick tests never leave again; the compliance laws need it too, whose kink at the
//    obstacle surface makes full steps cycle between two branches. The thesis's methods take
//    full steps on frictionless Signorini contact (Tables 7.1, 7.2), and so do we.
#include "contact/contact_kernel.hpp"
#include "contact/contact_law.hpp"
#include "contact/contact_status.hpp"
#include "solver/contact_bulk.hpp"
#include "solver/contact_method.hpp"

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
  Eigen::VectorXd t;      ///< tangential multipliers
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
  /// Per contact node, 1 if on the wall in the iteration's step: the active set itself, to see
  /// where it moves (a contact patch travelling one node per iteration, scene 7b).
  std::vector<std::int8_t> wall;
};

struct ContactNewtonOptions {
  double eps = 1e-5;
  int max_iterations = 100;
  bool line_search = false; ///< on a linear bulk (a nonlinear one always searches)
};

/// The options of `parameters`, the line search resolved for a problem of these `laws`.
ContactNewtonOptions newton_options(const ContactSolverParameters& parameters,
                                    const std::vector<ContactLaw>& laws);

struct ContactNewtonResult {
  bool converged = false;
  std::string failure; ///< why it stopped without converging
  std::vector<IterationRecord> history;
  std::vector<double> step_length;  ///< line-search alpha per iteration (1 for linear bulks)
  Eigen::VectorXd normal_force;     ///< N per node at the end (nodal force, >= 0 at a solution)
  Eigen::VectorXd tangential_force; ///< T per node
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
