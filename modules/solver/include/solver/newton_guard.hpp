#pragma once
// The bookkeeping of the contact Newton driver's globalization (contact_newton.hpp): which merit
// a step must beat, whether the branches cycle, and the name of a failure. Pure logic on the
// merits and the branch sets the driver hands in, so that each rule is tested alone.
//
//  - Armijo's test on theta = ||R||^2 / 2, the Newton direction's slope being -2 theta(x_k):
//        theta(x + alpha d) <= theta_ref - 2 sigma alpha theta(x_k).
//    The driver takes theta_ref = theta(x_k) on the residual of the system the step linearized
//    (its branches held), and bounds the trial's own residual by kRelaxation times the largest
//    merit of the last M iterates (MeritMemory), the reference of Grippo, Lampariello and Lucidi's
//    nonmonotone search ("A nonmonotone line search technique for Newton's method", SIAM J.
//    Numer. Anal. 23, 1986): an active-set change may raise the residual for a while, as the
//    next test puts it right, but not without bound. A raise must be repaid within kWatchSteps
//    steps (2 kWatchSteps at most on a path whose rate promises it), else the driver returns to
//    where it started (the watchdog, contact_newton.hpp).
//  - Cycling: the semi-smooth Newton of a complementarity problem can return to a branch set
//    (active set, stick and slip) it left without any progress (PDAS cycles on P-matrices that are
//    not M-matrices; Coulomb friction is not even monotone). A branch set that repeats one of the
//    last iterations' while the best merit has not fallen below the merit it had then is a cycle;
//    the driver answers it by restricting the steps (Murty's one change per iteration on an LCP,
//    monotone steps, whose strictly falling merit cannot revisit a point, otherwise), then
//    by the other restriction, and names a cycle with no restriction left a failure.
//  - Damping (a nonlinear bulk): a Newton step along which the search finds only a short length
//    that barely lowers the merit is a tangent near singular at the iterate (a soft mode the
//    linearization sends far, the crushed ring of scene 7b on a mesh not its own: 60 steps of
//    1/64 each); the next solves add mu times the bulk's rest stiffness diagonal to the tangent,
//    Levenberg and Marquardt's damping, mu grown tenfold from tau = 1e-3 while such steps go on
//    and cut tenfold, to 0 below tau, after any other (K. Madsen, H. B. Nielsen, O. Tingleff,
//    "Methods for non-linear least squares problems", DTU 2004, 3.2: tau = 1e-3 from a poor
//    start). Undamped steps are left as they were.
//  - Stagnation: no new least merit for kProgressWindow iterations makes the steps monotone;
//    monotone steps that cannot lower the merit kEscapes + 1 times in a row, or a least merit
//    kProgressWindow iterations old at the iteration limit, are a stagnation.
#include "contact/contact_kernel.hpp"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace sig {

/// Why a contact solve stopped without converging (summary.json's `failure`).
enum class NewtonFailure {
  none,
  cycling,         ///< the branch sets repeat without progress, monotone steps included
  stagnation,      ///< the residual no longer falls
  divergence,      ///< the residual or the iterate grew without bound, or is not finite
  drift,           ///< a rigid motion that no contact or friction holds (the load is not held)
  iteration_limit, ///< still progressing at the iteration limit
  singular_step,   ///< the step's matrix could not be factorized
};

/// "cycling", "stagnation", "divergence", "drift", "iteration-limit", "singular-step".
std::string name(NewtonFailure failure);

/// The merits the nonmonotone Armijo test compares with (header).
class MeritMemory {
public:
  /// `window` M >= 1 merits remembered.
  explicit MeritMemory(int window);
  /// The merit ||R|| of an accepted iterate.
  void push(double residual);
  /// max_j theta(x_{k-j}) over the window, as ||R|| (theta's square root).
  double reference() const;

private:
  int window_;
  std::deque<double> residuals_;
};

/// Armijo's constant sigma of the sufficient decrease.
inline constexpr double kArmijo = 1e-4;

/// Armijo's test of a trial residual at step length alpha against a reference (header), in norms:
/// ||R_trial||^2 <= reference^2 - 2 sigma alpha ||R_k||^2.
bool sufficient_decrease(double trial, double reference, double current, double alpha);

/// The watchdog's extension (contact_newton.hpp): whether a step that took the merit from
/// `before` to `now` contracted it fast enough that kWatchSteps more steps at that rate would
/// repay a raise that started at `start` (Armijo's test against it). A path converging linearly
/// after a cold start's raise is let go on; one that rises or crawls is not.
bool rate_repays(double now, double before, double start);

/// Detects cycles of the branch sets (header).
class CycleGuard {
public:
  /// Remember `window` iterations.
  explicit CycleGuard(int window);
  /// The iterate at which the branches `branch` were tested had merit `residual`. True if that
  /// branch set is one of the window's but the last (a period of at least two) and no merit
  /// since then fell below (1 - kProgress) times the merit it had.
  bool repeats(const std::vector<KernelBranch>& branch, double residual);

  /// Relative fall of the merit that counts as progress between two visits of a branch set.
  static constexpr double kProgress = 1e-3;

private:
  struct Visit {
    std::uint64_t hash;
    std::vector<KernelBranch> branch;
    double residual;
    double lowest_since; ///< the lowest merit seen after this visit
  };
  int window_;
  std::deque<Visit> visits_;
};

/// The Levenberg-Marquardt damping of a nonlinear bulk's steps (header).
class Damping {
public:
  /// After a searched step of length alpha whose merit is `ratio` times the one before.
  void after_step(double alpha, double ratio);
  /// mu: the multiple of the rest stiffness diagonal the next tangent takes (0: undamped).
  double factor() const { return mu_; }

  /// A step this short ...
  static constexpr double kShortStep = 1.0 / 8;
  /// ... that keeps more than this part of the merit is a stall on a near-singular tangent.
  static constexpr double kStall = 0.9;
  /// tau, the first damping, and the factor it grows and shrinks by.
  static constexpr double kFirst = 1e-3;
  static constexpr double kGrowth = 10;

private:
  double mu_ = 0;
};

/// Iterates the relaxed test's reference remembers (M).
inline constexpr int kMeritWindow = 5;
/// The factor C by which a relaxed step may raise the residual over the reference.
inline constexpr double kRelaxation = 10;
/// Steps after a relaxed step that raised the merit within which it must fall below the merit
/// that step started from (the watchdog of contact_newton.hpp): while that merit is still one
/// of the kMeritWindow the nonmonotone reference remembers. A path whose rate promises the
/// repayment (rate_repays) gets one step more at a time, kWatchSteps at most: by then the start
/// has left the window, which does not matter, since a return restores the window as it was.
inline constexpr int kWatchSteps = kMeritWindow - 1;
/// Iterations a branch set is remembered for the cycle test.
inline constexpr int kCycleWindow = 30;
/// Monotone iterations in a row that may take a step that lowers nothing (an escape from a
/// kink where the Newton step is no descent) before the solve stagnates.
inline constexpr int kEscapes = 3;
/// Iterations without a new least residual after which the steps must be monotone.
inline constexpr int kProgressWindow = 10;
/// The relative precision of the merit: its rows are sums of nodal forces of the order of the
/// force scale, up to about 1e4 terms a row (a condensed operator is dense over the contact
/// nodes), each rounded to the unit round-off 1.1e-16 (a sum of n terms is exact to n u, Higham,
/// "Accuracy and stability of numerical algorithms", 2002, 4.2). Merits below it of the force
/// scale cannot be ranked.
inline constexpr double kMeritPrecision = 1e-12;

} // namespace sig
