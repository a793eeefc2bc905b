#pragma once
// The convexification loop (4.110)-(4.112) of the nonmonotone friction law (contact_law.hpp,
// (1.39)): the problem is non-convex in u through mu(r), so each outer iteration m freezes the
// coefficient of every nonmonotone node at the slip of the previous iterate, mu_i = mu(r_i(m)),
// and solves the convex problem that remains (Coulomb with a per-node mu) with the one Newton
// driver (contact_newton.hpp), warm-started from the previous iterate's displacement,
// multipliers and branches; on a linear bulk every outer step reuses the one condensed problem.
// The thesis's stopping test (l.7601, ALGORITHMS.md 1.3): both
//   ||u(m+1) - u(m)||_V <= eps ||u(m)||_V   and   ||xi(m+1) - xi(m)||_L2(Gamma3) <= eps ||xi(m)||,
// ||.||_V the caller's norm of V (the static stage: ||eps(u)||_L2 of the whole body),
// ||xi||^2 = sum_i w_i |xi_i|^2 with xi_i = (N_i, T_i) / w_i the contact pressures; m >= 1 (the
// test is undefined at the start u(0) = 0).
//
// [choice] Under-relaxation (off by default, theta = 1; the thesis has none) acts on the frozen
// coefficients: mu(m+1) = theta mu(r(m+1)) + (1 - theta) mu(m), the Krasnoselskii-Mann iteration
// of the fixed point mu = M(mu). ALGORITHMS.md 1.3 suggests relaxing u(m) against u(m-1); mu is
// bounded in [b, a] and needs no iterate before the first.
//
// The slip measure r is an input: |q_t| (the slip from the reference, of=slip, ch. 4) by
// default, the slip rate of a time step for ch. 6. A loop that does not converge is a result
// (converged = false, the failure and the history); so is an inner solve that does not. When the
// statuses of the nodes repeat with a period p >= 2 for kCycleRepeats periods, the loop stops
// and reports the cycle: the fixed point has stopped contracting (ALGORITHMS.md 1.3: the
// small-slope condition p0 m_mu + mu0 L_p < alpha0 fails).
#include "solver/contact_bulk.hpp"
#include "solver/contact_method.hpp"
#include "solver/contact_newton.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace sig {

/// Where the loop starts: mu(0) = a, the body at rest (u(0) = 0, ALGORITHMS.md 1.3, default),
/// mu = b, as if every node had slipped far, or the coefficients the setting holds (a march in
/// time: mu of the previous step's slip rate, ALGORITHMS.md 3.3).
enum class ConvexificationStart { rest, slipped, given };

struct ConvexificationOptions {
  double eps = 1e-5;        ///< outer tolerance of l.7601
  int max_iterations = 200; ///< outer iterations (convex solves)
  double relaxation = 1;    ///< theta in (0, 1]; 1: none
  ConvexificationStart start = ConvexificationStart::rest;
};

/// The measures the loop takes of the bulk's iterate (the driver never sees a mesh).
struct ConvexificationMeasures {
  /// r per contact node; empty: |q_t|, the magnitude of the bulk's slip (of=slip)
  std::function<Eigen::VectorXd(const ContactBulk&)> slip;
  /// The displacement whose V-norm the outer test takes (e.g. the whole body's nodal values)
  std::function<Eigen::VectorXd(const ContactBulk&)> displacement;
  /// ||v||_V; empty: the Euclidean norm
  std::function<double(const Eigen::VectorXd&)> norm;
};

/// One convex solve of the loop.
struct OuterRecord {
  int inner_iterations = 0;
  bool inner_converged = false;
  double displacement_change = 0; ///< ||u(m+1) - u(m)||_V / ||u(m)||_V (1 from u(m) = 0)
  double force_change = 0;        ///< ||xi(m+1) - xi(m)|| / ||xi(m)|| (1 from xi(m) = 0)
  double mu_change = 0;           ///< max_i |mu_i of this solve - mu_i of the previous one|
  int status_changes = 0;         ///< nodes whose (normal, friction) status changed
  int wall = 0, compliance = 0, stick = 0, slip = 0; ///< status counts after the solve
};

struct ConvexificationResult {
  bool converged = false;
  NewtonFailure reason = NewtonFailure::none; ///< the loop's cycle, a convex solve's failure, ...
  std::string failure;                        ///< why it stopped without converging
  std::vector<OuterRecord> history;
  int cycle = 0;            ///< period p >= 2 of the statuses' cycle, 0 if none was seen
  ContactNewtonResult last; ///< the last convex solve
  std::vector<IterationRecord> inner_history; ///< every inner iteration, in order
  Eigen::VectorXd mu; ///< per node, the coefficient of the last convex solve
  int outer_iterations() const { return static_cast<int>(history.size()); }
  int inner_iterations() const { return static_cast<int>(inner_history.size()); }
};

/// Statuses must repeat this many periods before the loop calls it a cycle and stops.
inline constexpr int kCycleRepeats = 3;

/// The loop (header) from the bulk's iterate and `iterate`, which end at the last convex solve;
/// the coefficients of the nodes of law nonmonotone are set per outer iteration, the others'
/// laws are left as `setting` has them. sig::Error for inconsistent sizes or options (eps <= 0,
/// max_iterations < 1, relaxation outside (0, 1]).
ConvexificationResult convexify(ContactBulk& bulk, const ContactSetting& setting,
                                const ContactMethod& method, const ContactNewtonOptions& inner,
                                const ConvexificationOptions& options,
                                const ConvexificationMeasures& measures, ContactIterate& iterate);

/// The smallest period p in [2, 16] with which the last kCycleRepeats p entries of `statuses`
/// (one code vector per outer iteration) repeat, the entries within a period not all equal; 0 if
/// none.
int status_cycle(const std::vector<std::vector<int>>& statuses);

/// Some law of `laws` is nonmonotone (its solve needs the loop).
bool needs_convexification(const std::vector<ContactLaw>& laws);

} // namespace sig
