// The semi-smooth Newton driver of contact_newton.hpp.
#include "solver/contact_newton.hpp"

#include "contact/contact_kernel.hpp"
#include "core/error.hpp"
#include "solver/newton_guard.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace sig {

namespace {

/// Halvings of a step before the search settles for its least merit.
constexpr int kMaxHalvings = 12;
/// A step whose proximal force carries more than this part of the residual is unheld.
constexpr double kUnheld = 1e-3;
/// A residual this many times the first one: divergence.
constexpr double kDivergence = 1e12;
/// det(I - A) of a 3D slip below which its step fixes the slip direction
/// (tangential_conditions_3d): sqrt(u), u the unit round-off.
const double kFixedDirectionEdge = std::sqrt(std::numeric_limits<double>::epsilon());

/// The contact state at the bulk's iterate.
struct ContactPoint {
  Eigen::VectorXd q_n, q_t;  ///< penetration and slip
  Eigen::VectorXd lambda, t; ///< multipliers (nodal forces)
  double residual = 0;       ///< ||R|| (header), absolute
};

/// The tangential quantities of the d-dimensional driver: per node a scalar (2D) or the two
/// components in the node's tangents (3D), stored flat (contact_bulk.hpp), node p's at
/// (d - 1) p.
template <int d> Tangent<d> tangent_at(const Eigen::VectorXd& v, int p) {
  if constexpr (d == 2)
    return v[p];
  else
    return v.template segment<d - 1>((d - 1) * p);
}
template <int d> void set_tangent(Eigen::VectorXd& v, int p, const Tangent<d>& x) {
  if constexpr (d == 2)
    v[p] = x;
  else
    v.template segment<d - 1>((d - 1) * p) = x;
}
inline double squared(double x) {
  return std::pow(x, 2);
}
template <int n> double squared(const Eigen::Matrix<double, n, 1>& x) {
  return x.squaredNorm();
}
/// A branch as a set of active, stick and slip nodes: in 3D the slip's direction turns
/// continuously and only whether the node slips makes the set (the cycles, the settled test,
/// a kink along a step); in 2D the branch itself.
template <int d> KernelBranch combinatorial(const KernelBranchIn<d>& b) {
  if constexpr (d == 2)
    return b;
  else
    return {b.wall, b.stick, b.slip.isZero() ? 0 : 1};
}
template <int d> std::vector<KernelBranch> combinatorial(const std::vector<KernelBranchIn<d>>& b) {
  if constexpr (d == 2) {
    return b;
  } else {
    std::vector<KernelBranch> c;
    c.reserve(b.size());
    for (const auto& x : b)
      c.push_back(combinatorial<d>(x));
    return c;
  }
}
/// A node's branch of the last iteration (as ContactIterate keeps it) to hold in a test: in 3D
/// its slip direction is the kernel's own wherever z != 0, zero at z = 0.
template <int d> KernelBranchIn<d> expanded(const KernelBranch& b) {
  if constexpr (d == 2)
    return b;
  else
    return {b.wall, b.stick, SlipDirection<d>::Zero()};
}
template <int d> bool slipping(const ContactKernelIn<d>& k) {
  if constexpr (d == 2)
    return k.slip != 0;
  else
    return !k.slip.isZero();
}

/// Step (ii) at an iterate: the branch of every node, its condition for step (iii), the record.
template <int d> struct Test {
  std::vector<KernelBranchIn<d>> branch;
  std::vector<NodeConditions> conditions;
  IterationRecord record;
};

/// Step (iii): the linear step and the multipliers it gives at its full length.
struct Step {
  StepSolution solution;
  Eigen::VectorXd lambda, t;
};

template <int d> class Driver {
  using Kernel = ContactKernelIn<d>;
  using Branch = KernelBranchIn<d>;
  using Tan = Tangent<d>;
  using Test = sig::Test<d>;

public:
  Driver(ContactBulk& bulk, const ContactSetting& setting, const ContactMethod& method,
         const ContactNewtonOptions& options)
      : bulk_(bulk), s_(setting), method_(method), options_(options), m_(setting.size()),
        friction_(bulk.has_tangential()) {
    static_assert(d == 2 || d == 3);
  }

  ContactNewtonResult run(ContactIterate& iterate);

private:
  ContactBulk& bulk_;
  const ContactSetting& s_;
  const ContactMethod& method_;
  const ContactNewtonOptions& options_;
  const int m_;
  const bool friction_;
  Eigen::VectorXd natural_; ///< per node: the bulk's stiffness over the weight (pressure / length)
  ContactNewtonResult result_;
  MeritMemory memory_{kMeritWindow};
  CycleGuard cycles_{kCycleWindow};
  Damping damping_; ///< a nonlinear bulk's steps (newton_guard.hpp)
  /// How the steps are taken (header): relaxed at first; monotone once the branches cycled or the
  /// residual stopped falling, one branch change per iteration too once they cycled again.
  bool one_change_ = false;
  bool monotone_ = false;
  double best_ = 0;      ///< the least residual so far
  int best_at_ = 0;      ///< its iteration
  std::int8_t kind_ = 0; ///< how the last step was taken (IterationRecord::kind)
  int escapes_ = 0;      ///< monotone iterations in a row that could not lower the residual
  double ratio_ = 0;     ///< the last searched step's merit after over before
  double drift_ = 0;     ///< the length of the last unheld step that nothing held
  int drift_at_ = 0;     ///< its iteration
  /// The watchdog (header): the driver's state at the iterate a relaxed step left with a higher
  /// merit (the bulk's is its checkpoint), until a later step repays the raise or kWatchSteps
  /// (and the extensions the path's rate earns) have not.
  struct Watch {
    ContactPoint before;
    ContactIterate iterate;
    MeritMemory memory;
    CycleGuard cycles;
    double best;
    int best_at;
    Damping damping;
    double drift;
    int drift_at;
    int left;         ///< steps left to repay it
    int extended = 0; ///< steps granted past kWatchSteps by the path's rate (run())
  };
  std::optional<Watch> watch_;
  /// The step from a watchdog's return: searched under a ceiling of the present merit (if no
  /// length stays under it, the least residual, as every search's fallback).
  bool returned_ = false;

  double weight(int p) const { return s_.weight[p]; }
  /// A residual at round-off, below the merit's precision and the stopping test's tolerance:
  /// merits there cannot be ranked (header), and a trial there from an iterate there passes
  /// every search.
  bool at_round_off(const ContactPoint& c) const {
    return c.residual <= std::min(options_.eps, kMeritPrecision) * bulk_.force_scale();
  }
  /// The kernel of node p at (q_n, q_t) with multipliers (lambda, t) as nodal forces (penalty:
  /// none), augmented by r (r_t on the slip if given), on the branch `on` if given.
  Kernel kernel(int p, double q_n, const Tan& q_t, double lambda, const Tan& t, double r,
                const Branch* on = nullptr, double r_t = 0) const;
  /// The method's test (ii): its augmentation r on the wall, and on the slip the smaller of r
  /// and the node's natural scale where the method has multipliers (header). Once the steps are
  /// monotone, a method with multipliers tests at the natural scale on both: its step is then
  /// the Newton step of the merit itself, a descent direction wherever the merit is smooth,
  /// which a step tested at another augmentation is not where the two tests choose different
  /// branches (a monotone search along it stalls there: Tresca's half disc at r = 316 E / h).
  Kernel tested(int p, double q_n, const Tan& q_t, double lambda, const Tan& t,
                const Branch* on = nullptr) const {
    return kernel(p, q_n, q_t, lambda, t, normal_augmentation(p), on, tangential_augmentation(p));
  }
  bool tests_the_merit() const { return monotone_ && method_.has_multipliers(); }
  double normal_augmentation(int p) const {
    return tests_the_merit() ? natural_[p] : method_.augmentation();
  }
  double tangential_augmentation(int p) const {
    const double r = method_.augmentation();
    if (tests_the_merit()) return natural_[p];
    return method_.has_multipliers() ? std::min(r, natural_[p]) : r;
  }
  ContactPoint point(const Eigen::VectorXd& lambda, const Eigen::VectorXd& t,
                     const std::vector<Branch>* held = nullptr,
                     const Eigen::VectorXd* origin = nullptr) const;
  NodeConditions node_conditions(int p, const Kernel& k, double q_n, const Tan& q_t,
                                 const Tan& t) const;
  void tangential_conditions_3d(int p, const Kernel& k, const Tan& q_t, const Tan& t,
                                NodeConditions& c) const;

  void start(ContactIterate& iterate);
  Test test(const ContactPoint& now, const ContactIterate& iterate, bool one_change);
  bool solve(const Test& test, const ContactPoint& now, Step& step);
  bool trial(double alpha, const ContactPoint& now, const Step& step, ContactPoint& at);
  double step_length(const Test& test, const ContactPoint& now, const Step& step,
                     ContactPoint& next);
  double unheld_length(const ContactPoint& now, const Step& step, ContactPoint& next);
  double searched_length(const Test& test, const ContactPoint& now, const Step& step,
                         ContactPoint& next);
  template <class Departs>
  std::vector<double> crossings(const ContactPoint& from, const ContactPoint& to, Departs departs,
                                bool only_first) const;
  double first_hold(const ContactPoint& from, const ContactPoint& to) const;
  std::vector<double> kinks(const ContactPoint& from, const ContactPoint& to) const;
  double monotone_length(const ContactPoint& now, const Step& step, ContactPoint& next);
  void record(Test& test, const ContactPoint& before, const ContactPoint& now, double alpha);
  bool stopped(int iteration, double first_residual);
  /// The next restriction of the steps after a cycle or a stall: first one branch change per
  /// iteration with full steps for a linear complementarity problem (frictionless Signorini on a
  /// linear bulk, a P-matrix LCP, where Murty's rule terminates), monotone steps for the other
  /// problems, whose full steps Murty's rule does not tame (a compliance's kink on one node); then
  /// the other restriction too. False if none is left. The cycles are then counted afresh.
  bool restrict_steps() {
    if (one_change_ && monotone_) return false;
    const bool lcp = !bulk_.nonlinear() && !s_.has_friction() &&
                     std::none_of(s_.law.begin(), s_.law.end(),
                                  [](const ContactLaw& l) { return l.has_compliance(); });
    if (one_change_ || monotone_)
      one_change_ = monotone_ = true;
    else
      (lcp ? one_change_ : monotone_) = true;
    cycles_ = CycleGuard(kCycleWindow);
    escapes_ = 0;
    return true;
  }
  /// Back to the iterate before a nonmonotone step that the watch's steps did not repay (header):
  /// an unheld step undone with it is no longer a drift.
  void return_to(Watch& w, ContactPoint& now, ContactIterate& iterate) {
    bulk_.rewind();
    now = std::move(w.before);
    iterate = std::move(w.iterate);
    memory_ = std::move(w.memory);
    cycles_ = std::move(w.cycles);
    best_ = w.best;
    best_at_ = w.best_at;
    damping_ = w.damping;
    bulk_.damp(damping_.factor());
    drift_ = w.drift;
    drift_at_ = w.drift_at;
    returned_ = true;
  }
  void fail(NewtonFailure why, const std::string& detail) {
    result_.reason = why;
    result_.failure = name(why) + ": " + detail;
  }
  void finish(const ContactPoint& now);
};

/// The kernel of node p at (q_n, q_t) with multipliers (lambda, t) as nodal forces (penalty:
/// none), augmented by r, on the branch `on` if given.
template <int d>
ContactKernelIn<d> Driver<d>::kernel(int p, double q_n, const Tan& q_t, double lambda, const Tan& t,
                                     double r, const Branch* on, double r_t) const {
  NodeVariablesIn<d> x{q_n, q_t, 0.0, zero_tangent<d>()};
  if (method_.has_multipliers()) {
    x.lambda = lambda / weight(p);
    x.t = t / weight(p);
  }
  if (r_t == 0) r_t = r;
  return on ? contact_kernel(s_.law[p], x, r, r_t, *on) : contact_kernel(s_.law[p], x, r, r_t);
}

/// The state at the bulk's iterate with multipliers (lambda, t), and its residual
/// ||R|| = ||(equilibrium, w C_n, w C_t)|| (header): the equilibrium with the contact forces of
/// the iterate (compliance plus multipliers, or penalty's springs) and the Alart-Curnier
/// functions at each node's natural augmentation; on the branches `held` of a step's test if
/// given, whose off-wall rows are then the step's condition there (lambda = 0, or projection's
/// Robin law from the step's origin `origin`).
template <int d>
ContactPoint Driver<d>::point(const Eigen::VectorXd& lambda, const Eigen::VectorXd& t,
                              const std::vector<Branch>* held,
                              const Eigen::VectorXd* origin) const {
  ContactPoint c{bulk_.penetration(), bulk_.slip(), lambda, t, 0.0};
  Eigen::VectorXd N(m_), T((d - 1) * m_);
  double complementarity = 0;
  for (int p = 0; p < m_; ++p) {
    const Branch* on = held ? &(*held)[p] : nullptr;
    if (method_.has_multipliers()) {
      const Kernel k = kernel(p, c.q_n[p], tangent_at<d>(c.q_t, p), lambda[p], tangent_at<d>(t, p),
                              natural_[p], on);
      N[p] = weight(p) * k.compliance + lambda[p];
      set_tangent<d>(T, p, tangent_at<d>(t, p));
      Eigen::Matrix<double, d, 1> C = weight(p) * k.complementarity;
      if (on && !on->wall)
        C[0] -= off_wall_stiffness(method_, s_.law[p], weight(p)) * (c.q_n[p] - (*origin)[p]);
      complementarity += C.squaredNorm();
    } else { // penalty: its springs are the model, their r is not an algorithm's parameter
      const Kernel k = kernel(p, c.q_n[p], tangent_at<d>(c.q_t, p), 0.0, zero_tangent<d>(),
                              method_.augmentation(), on);
      N[p] = weight(p) * k.normal;
      set_tangent<d>(T, p, weight(p) * k.tangential);
    }
  }
  c.residual = std::sqrt(std::pow(bulk_.equilibrium_residual(N, T), 2) + complementarity);
  return c;
}

/// Step (iii): the condition of node p on the branch of kernel k at slip q_t and tangential
/// multiplier t (a nodal force).
template <int d>
NodeConditions Driver<d>::node_conditions(int p, const Kernel& k, double q_n, const Tan& q_t,
                                          const Tan& t) const {
  const ContactLaw& law = s_.law[p];
  const double w = weight(p);
  NodeConditions c;
  if (method_.has_multipliers() && k.wall_active) {
    c.normal.imposed = true;
    c.normal.value = law.depth - q_n;
  } else {
    c.normal.force = w * k.normal;
    c.normal.stiffness = w * k.d_force(0, kQn) + off_wall_stiffness(method_, law, w);
  }
  if (!law.has_friction()) return c;
  if constexpr (d == 2) {
    (void)t;
    if (k.stick && method_.has_multipliers()) {
      c.tangential.imposed = true;
      c.tangential.value = law.held_slip[0] - q_t; // stick: back to the slip it holds, 0 or held
    } else if (k.stick) {
      c.tangential.force = w * k.tangential;
      c.tangential.stiffness = w * k.d_force(1, kQt);
    } else if (k.bound_slope != 0 && c.normal.imposed) {
      c.tangential.coupling = k.slip * k.bound_slope; // T = sigma mu N, N the wall's reaction
    } else {
      // T = sigma s with s the kernel's bound law: a threshold, mu p(q_n) (bound=compliance), or
      // mu N with N the kernel's normal force law, not the projection's Robin term (a
      // relaxation of the inactive nodes, not a contact force).
      c.tangential.force = w * k.slip * k.bound;
      c.tangential.cross = w * k.slip * k.d_bound(kQn);
    }
  } else {
    tangential_conditions_3d(p, k, q_t, t, c);
  }
  return c;
}

/// The 3D tangential conditions of node p (d = 3): a component a DIRICHLET card holds back to
/// its slip, the other by the 2D law of its line; stick, both slips held (multipliers) or
/// penalty's spring; slip, the force T = s e, e = z / |z|, z = t + r_t q_t, whose Newton step on
/// C_t = t - T(t, q_t) = 0 is (I - A) dt = T - t + B dq_t + e ds with A = dT/dt = s (I - e e^T)
/// / |z| and B = dT/dq_t = r_t A: the step's multiplier, t + dt, is then the force law
///     T+ = (I - M) t + e (s + ds) + M B dq_t,   M = (I - A)^-1
/// (M e = e), s + ds = mu N+ with Coulomb's bound on the wall (N+ its reaction: the coupling e mu)
/// or s's own law in q_n (cross). In 2D A = B = 0 and this is the scalar law above, T = sigma s.
/// Penalty (no multipliers) takes T = w T(q_t) + w B dq_t.
template <int d>
void Driver<d>::tangential_conditions_3d(int p, const Kernel& k, const Tan& q_t, const Tan& t,
                                         NodeConditions& c) const {
  using Block = Eigen::Matrix<double, d - 1, d - 1>;
  using Col = KernelColumns<d>;
  const double w = weight(p);
  const bool multipliers = method_.has_multipliers();
  Tan force = Tan::Zero(), coupling = Tan::Zero(), cross = Tan::Zero();
  Block stiffness = Block::Zero();
  const auto rows = k.d_force.template bottomRows<d - 1>();
  const Block B = rows.template middleCols<d - 1>(Col::q_t);
  const ContactLaw& law = s_.law[p];
  if (law.held_tangential()) { // multipliers: penalty cannot hold a component (static_solve)
    // Per component: a held one back to its slip, the free one as in 2D (the line's law).
    for (int i = 0; i < d - 1; ++i) {
      DofCondition& ci = c.tangent(i);
      if (law.held_tangent[i] || k.stick) {
        ci.imposed = true;
        ci.value = (law.held_tangent[i] ? law.held_slip[i] : 0.0) - q_t[i];
      } else if (k.bound_slope != 0 && c.normal.imposed) {
        ci.coupling = k.slip[i] * k.bound_slope;
      } else {
        ci.force = w * k.slip[i] * k.bound;
        ci.cross = w * k.slip[i] * k.d_bound(Col::q_n);
      }
    }
    return;
  }
  if (k.stick && multipliers) {
    for (int i = 0; i < d - 1; ++i) {
      c.tangent(i).imposed = true;
      c.tangent(i).value = -q_t[i]; // back to no slip
    }
    return;
  }
  if (k.stick) {
    force = w * k.tangential;
    stiffness = w * B;
  } else if (!multipliers) {
    force = w * k.tangential;
    stiffness = w * B;
    cross = w * k.slip * k.d_bound(Col::q_n);
  } else {
    const Block A = rows.template middleCols<d - 1>(Col::t);
    const Block I_A = Block::Identity() - A;
    // det(I - A) = 1 - s / |z|: singular with z on the disc's edge (a held slip branch, or a
    // node that reaches the edge exactly); the step then treats the direction as fixed, as in
    // 2D: T = s e, M = I and no stiffness in the slip. Near the edge (a slip rate going to 0 at
    // the bound: a degenerate solution) M amplifies the rounding of t across e by 1 / det, a
    // floor of about u / det of the force (u the unit round-off), where fixing the direction
    // errs by about det: the direction is fixed below det = sqrt(u), where the two balance (the
    // backward-Euler pad of datafiles/scene3d/creep_slip.dat slipping to rest stalled at 1e-9 of
    // the force with eps = 1e-10 when only det <= 1e-12 was fixed).
    const bool fixed_direction = std::abs(I_A.determinant()) <= kFixedDirectionEdge;
    const Block M = fixed_direction ? Block::Identity() : Block(I_A.inverse());
    const Tan x_t = t / w; // the multiplier as a pressure, as the kernel's
    stiffness = fixed_direction ? Block::Zero() : Block(w * M * B);
    force = w * (Block::Identity() - M) * x_t;
    if (k.bound_slope != 0 && c.normal.imposed) {
      coupling = k.slip * k.bound_slope;
    } else {
      force += w * k.slip * k.bound;
      cross = w * k.slip * k.d_bound(Col::q_n);
    }
  }
  for (int i = 0; i < d - 1; ++i) {
    DofCondition& ci = c.tangent(i);
    ci.force = force[i];
    ci.stiffness = stiffness(i, i);
    ci.coupling = coupling[i];
    ci.cross = cross[i];
  }
  c.tangential_12 = 0.5 * (stiffness(0, 1) + stiffness(1, 0));
}

template <int d> void Driver<d>::start(ContactIterate& iterate) {
  if (iterate.lambda.size() == 0) iterate.lambda = Eigen::VectorXd::Zero(m_);
  if (iterate.t.size() == 0) iterate.t = Eigen::VectorXd::Zero((d - 1) * m_);
  SIG_VERIFY(bulk_.contacts() == m_ && s_.weight.size() == m_ && iterate.lambda.size() == m_ &&
                 iterate.t.size() == (d - 1) * m_,
             "contact Newton: the bulk has " << bulk_.contacts() << " contact nodes, the setting "
                                             << m_);
  SIG_VERIFY(friction_ || !s_.has_friction(),
             "contact Newton: a friction law on a bulk without tangential unknowns");
  if (!method_.has_multipliers()) {
    iterate.lambda.setZero();
    iterate.t.setZero();
  }
  natural_ = bulk_.contact_stiffness();
  SIG_VERIFY(natural_.size() == m_,
             "contact Newton: " << natural_.size() << " nodal stiffnesses for " << m_);
  for (int p = 0; p < m_; ++p)
    natural_[p] = natural_[p] > 0 ? natural_[p] / weight(p) : method_.augmentation();
}

/// Step (ii): the branches at the iterate, and (iii)'s conditions on them. With `one_change`,
/// only the first node (least index) whose branch differs from the last iteration's changes it,
/// the others keep theirs: Murty's least-index rule, whose principal pivoting terminates on
/// every P-matrix (a linear bulk's frictionless contact) where the block changes of the active
/// set may cycle (Murty, "Note on a Bard-type scheme for solving the complementarity problem",
/// Opsearch 11, 1974; Judice and Pires, Comput. Oper. Res. 21, 1994, as the fallback of block
/// principal pivoting).
template <int d>
Test<d> Driver<d>::test(const ContactPoint& now, const ContactIterate& iterate, bool one_change) {
  Test test{std::vector<Branch>(m_), std::vector<NodeConditions>(m_), {}};
  IterationRecord& record = test.record;
  record.wall.resize(m_);
  result_.normal_status.resize(m_);
  result_.friction_status.resize(m_);
  bool changed = false;
  for (int p = 0; p < m_; ++p) {
    const bool was_on_wall = !iterate.branch.empty() && iterate.branch[p].wall;
    const bool was_inactive = !iterate.branch.empty() && !was_on_wall;
    const double lambda = method_.tested_multiplier(iterate.lambda[p], was_inactive);
    const Tan q_t = tangent_at<d>(now.q_t, p), t = tangent_at<d>(iterate.t, p);
    Kernel k = tested(p, now.q_n[p], q_t, lambda, t);
    if (one_change && combinatorial<d>(branch_of(k)) != iterate.branch[p]) {
      if (changed) {
        const Branch held = expanded<d>(iterate.branch[p]);
        k = tested(p, now.q_n[p], q_t, lambda, t, &held);
      }
      changed = true;
    }
    test.branch[p] = branch_of(k);
    test.conditions[p] = node_conditions(p, k, now.q_n[p], q_t, t);
    record.active += k.wall_active && !k.held ? 1 : 0;
    record.wall[p] = k.wall_active && !k.held ? 1 : 0;
    if (!k.held && k.wall_active != was_on_wall) ++(k.wall_active ? record.entered : record.left);
    record.stick += k.stick ? 1 : 0;
    record.slip += slipping<d>(k) && k.bound > 0 ? 1 : 0;
    // The statuses of the last test, so a failed iteration still reports where it stood.
    result_.normal_status[p] = normal_status(k);
    result_.friction_status[p] = friction_status(s_.law[p], k);
  }
  return test;
}

/// Step (iii): the linear step and the multipliers at its full length; false if its matrix
/// cannot be factorized.
template <int d> bool Driver<d>::solve(const Test& test, const ContactPoint& now, Step& step) {
  try {
    Eigen::VectorXd N = now.lambda; // the present normal forces (an obstacle's curvature)
    for (int p = 0; p < m_; ++p)
      N[p] += weight(p) * compliance_pressure(s_.law[p], now.q_n[p]);
    step.solution = bulk_.solve(test.conditions, N);
  } catch (const Error& e) {
    fail(NewtonFailure::singular_step,
         std::string("the generalized Jacobian could not be factorized: ") + e.what() + " (" +
             std::to_string(test.record.active) + " nodes on the wall)");
    return false;
  }
  step.lambda = Eigen::VectorXd::Zero(m_);
  step.t = Eigen::VectorXd::Zero((d - 1) * m_);
  if (!method_.has_multipliers()) return true;
  for (int p = 0; p < m_; ++p) {
    const ContactLaw& law = s_.law[p];
    if (test.conditions[p].normal.imposed) // the reaction, less the compliance at the wall
      step.lambda[p] =
          step.solution.normal_force[p] - weight(p) * compliance_pressure(law, law.depth);
    else // projection's Robin force, 0 for the Neumann condition
      step.lambda[p] =
          off_wall_stiffness(method_, law, weight(p)) * step.solution.normal_increment[p];
    if (law.has_friction())
      set_tangent<d>(step.t, p, tangent_at<d>(step.solution.tangential_force, p));
  }
  return true;
}

/// The bulk moved to alpha along the step, its state in `at`; false outside the bulk's domain
/// (an inverted element) or with a residual that is not finite.
template <int d>
bool Driver<d>::trial(double alpha, const ContactPoint& now, const Step& step, ContactPoint& at) {
  if (!bulk_.move(alpha)) return false;
  at = point(now.lambda + alpha * (step.lambda - now.lambda), now.t + alpha * (step.t - now.t));
  return std::isfinite(at.residual);
}

/// The step's length (header), the bulk left at it and its state in `next`; 0 if no length is
/// admissible (the failure set).
template <int d>
double Driver<d>::step_length(const Test& test, const ContactPoint& now, const Step& step,
                              ContactPoint& next) {
  if (!options_.globalize) {
    if (!trial(1.0, now, step, next)) {
      fail(NewtonFailure::divergence, "the full step leaves the bulk's domain (an inverted "
                                      "element) or gives a residual that is not finite");
      return 0.0;
    }
    bulk_.keep();
    return 1.0;
  }
  if (step.solution.proximal_force > kUnheld * std::max(now.residual, 1e-300)) {
    kind_ = 1;
    ratio_ = 0;
    const double alpha = unheld_length(now, step, next);
    if (alpha > 0 || result_.reason != NewtonFailure::none) return alpha;
  }
  kind_ = monotone_ ? 2 : one_change_ ? 3 : 0;
  const double alpha = searched_length(test, now, step, next);
  if (bulk_.nonlinear() && alpha > 0) { // a stall on a near-singular tangent damps the next
    damping_.after_step(alpha, ratio_);
    bulk_.damp(damping_.factor());
  }
  return alpha;
}

/// An unheld step (header): cut where a node first comes to hold the body; 0 if none does along
/// it (the step is then searched as any other, and remembered as a drift).
template <int d>
double Driver<d>::unheld_length(const ContactPoint& now, const Step& step, ContactPoint& next) {
  ContactPoint full;
  if (!trial(1.0, now, step, full)) {
    fail(NewtonFailure::divergence, "the unheld step's full length is not admissible");
    return 0.0;
  }
  double alpha = first_hold(now, full);
  if (!std::isfinite(alpha)) {
    drift_ = bulk_.displacement_step();
    drift_at_ = static_cast<int>(result_.history.size()) + 1;
    return 0.0;
  }
  alpha = std::min(1.0, alpha * (1 + 1e-9)); // just past the kink, so the node is in
  if (!trial(alpha, now, step, next)) return 0.0;
  bulk_.keep();
  return alpha;
}

/// The first alpha = 1, 1/2, ... whose trial passes the test of the mode (header): relaxed, the
/// residual of the system the step linearized (its branches held) falls by Armijo's test and the
/// residual itself stays below kRelaxation times the reference; monotone, the residual falls by
/// Armijo's test. If none passes, the admissible trial of least merit.
template <int d>
double Driver<d>::searched_length(const Test& test, const ContactPoint& now, const Step& step,
                                  ContactPoint& next) {
  const Eigen::VectorXd origin = now.q_n;
  const std::vector<Branch>* held = monotone_ ? nullptr : &test.branch;
  const auto merit = [&](const ContactPoint& c) {
    return held ? point(c.lambda, c.t, held, &origin).residual : c.residual;
  };
  const double current = merit(now);
  // From a watchdog's return, the step that was not repaid is searched under the present merit.
  const double ceiling = returned_ ? now.residual : kRelaxation * memory_.reference();
  if (monotone_) return monotone_length(now, step, next);
  // The fallback if no length passes: the largest admissible length below the ceiling (an
  // active-set change may raise the residual for a step), else the least residual.
  ContactPoint candidate;
  // The first step of a contact solve, whose branches are the start's (a cold active set), from
  // the longest length the bulk trusts its linearization over (header), halving; if none of
  // those passes, the longer halvings of the full step beyond it, as every other step.
  const bool cold = result_.history.empty() && m_ > 0;
  const double longest = cold ? std::min(1.0, bulk_.trusted_length()) : 1.0;
  std::vector<double> lengths;
  for (int h = 0; h <= kMaxHalvings; ++h)
    lengths.push_back(longest * std::ldexp(1.0, -h));
  for (int h = 0; longest < 1 && std::ldexp(1.0, -h) > longest; ++h)
    lengths.push_back(std::ldexp(1.0, -h));
  double fallback = std::numeric_limits<double>::infinity(), taken = 0;
  for (const double alpha : lengths) {
    if (!trial(alpha, now, step, candidate)) continue;
    const bool trusted = one_change_ || !method_.has_multipliers() || candidate.residual <= ceiling;
    const bool passes = (at_round_off(now) && at_round_off(candidate)) ||
                        (trusted && sufficient_decrease(merit(candidate), current, current, alpha));
    const double rank = held && trusted ? -alpha : candidate.residual; // lower is better
    if (passes || rank < fallback) {
      fallback = rank;
      taken = alpha;
      ratio_ = merit(candidate) / std::max(current, 1e-300);
      std::swap(next, candidate);
      bulk_.keep();
    }
    if (passes) break;
  }
  if (ratio_ >= 1) kind_ = 4;
  if (taken == 0)
    fail(NewtonFailure::divergence,
         "every step length down to 2^-" + std::to_string(kMaxHalvings) +
             " leaves the bulk's domain (an inverted element) or gives a residual that is not "
             "finite");
  return taken;
}

/// A monotone step (header): the length of least residual among the halvings and, on a linear
/// bulk, the breakpoints of the residual along the step (each node's first kink: up to the first
/// one the step is the Newton step of the pieces it linearized, so the residual falls there by
/// the fraction taken, where every halving may land beyond some kink); 0 if none is admissible
/// or none has lowered the residual kEscapes + 1 times in a row (the failure set).
template <int d>
double Driver<d>::monotone_length(const ContactPoint& now, const Step& step, ContactPoint& next) {
  std::vector<double> lengths;
  for (int h = 0; h <= kMaxHalvings; ++h)
    lengths.push_back(std::ldexp(1.0, -h));
  ContactPoint candidate;
  if (!bulk_.nonlinear() && trial(1.0, now, step, candidate))
    for (double kink : kinks(now, candidate))
      if (kink > std::ldexp(1.0, -kMaxHalvings) && kink < 1) lengths.push_back(kink);
  // Where no length lowers it (the step is no descent at a kink of the residual) the least one
  // is taken all the same, kEscapes times in a row at most: the next test sees other branches.
  // From an iterate at round-off, the first length at round-off is taken as it stands (header).
  double least = std::numeric_limits<double>::infinity(), taken = 0;
  bool rounded = false;
  for (const double alpha : lengths) {
    if (!trial(alpha, now, step, candidate)) continue;
    rounded = at_round_off(now) && at_round_off(candidate);
    if (candidate.residual < least || rounded) {
      least = candidate.residual;
      taken = alpha;
      std::swap(next, candidate);
      bulk_.keep();
    }
    if (rounded) break;
  }
  escapes_ = least < now.residual || rounded ? 0 : escapes_ + 1;
  ratio_ = least / std::max(now.residual, 1e-300);
  if (escapes_ > 0) kind_ = 4;
  // Stuck at a kink: the next restriction, if one is left.
  if (escapes_ > kEscapes) restrict_steps();
  if (taken == 0)
    fail(NewtonFailure::divergence, "every step length leaves the bulk's domain (an inverted "
                                    "element) or gives a residual that is not finite");
  else if (escapes_ > kEscapes)
    fail(NewtonFailure::stagnation, "no step length lowers the residual along the Newton step (" +
                                        std::to_string(escapes_) +
                                        " monotone iterations in a row, the residual " +
                                        std::to_string(now.residual / bulk_.force_scale()) + ")");
  return escapes_ > kEscapes ? 0.0 : taken;
}

/// Along a step from `from` (alpha = 0) to `to` (alpha = 1), the node variables affine in
/// alpha (exact on a linear bulk), per node the first alpha in (2^-60, 1] at which its kernel
/// differs from the one it had at 2^-60 by `departs(at_start, at_alpha)` (nodes that never do
/// are left out; with `only_first`, only crossings before the least found so far). Geometric
/// samples up from 2^-60 (an unheld step is long), then bisection. With `only_first` (where a
/// node first holds) and penalty, also the sample where the node's slip passes closest to 0:
/// penalty's stick window |q_t| <= s / r, narrower than the samples' spacing at a large r and
/// crossed in the middle of a step that reverses the slip, lies around it (exactly for a constant
/// bound, Tresca's; near it for Coulomb's, which moves with q_n), and missing it took a held body
/// for a drift (the Tresca half disc at r >= 30 E / h). A method with multipliers
/// sticks where |t / w + r q_t| <= s, its multiplier moving with the step: sampling its slip's
/// closest approach there cut the Tresca half disc's unheld steps elsewhere and made 9 points of
/// its map cycle (drivers/robustness.sh, m64 from the scene's start).
template <int d>
template <class Departs>
std::vector<double> Driver<d>::crossings(const ContactPoint& from, const ContactPoint& to,
                                         Departs departs, bool only_first) const {
  const auto at = [&](int p, double a) {
    const auto mix = [a](double x0, double x1) { return x0 + a * (x1 - x0); };
    const auto mix_t = [a](const Tan& x0, const Tan& x1) -> Tan { return x0 + a * (x1 - x0); };
    return tested(
        p, mix(from.q_n[p], to.q_n[p]), mix_t(tangent_at<d>(from.q_t, p), tangent_at<d>(to.q_t, p)),
        mix(from.lambda[p], to.lambda[p]), mix_t(tangent_at<d>(from.t, p), tangent_at<d>(to.t, p)));
  };
  constexpr int kFirst = 60;
  double first = std::numeric_limits<double>::infinity();
  std::vector<double> found;
  for (int p = 0; p < m_; ++p) {
    const Kernel start = at(p, std::ldexp(1.0, -kFirst));
    double below = 0, above = -1;
    for (int j = kFirst - 1; j >= 0 && above < 0; --j) {
      const double a = std::ldexp(1.0, -j);
      if (a >= first) break;
      (departs(start, at(p, a)) ? above : below) = a;
    }
    if (only_first && friction_ && !method_.has_multipliers()) {
      const Tan q0 = tangent_at<d>(from.q_t, p), dq = Tan(tangent_at<d>(to.q_t, p) - q0);
      const double dq2 = squared(dq);
      // argmin |q0 + a dq|: a = -q0.dq / |dq|^2, the dot product from the squared norms.
      const double closest = dq2 > 0 ? -(squared(Tan(q0 + dq)) - squared(q0) - dq2) / (2 * dq2) : 0;
      // Below the first departing sample (and the first crossing found), the power of 2 under
      // it was sampled and did not depart: the bisection's lower end.
      const double limit = std::min(above < 0 ? 1.0 : above, first);
      if (closest > std::ldexp(1.0, -kFirst) && closest < limit && departs(start, at(p, closest))) {
        below = std::ldexp(1.0, std::ilogb(closest));
        above = closest;
      }
    }
    if (above < 0) continue;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (below + above);
      (departs(start, at(p, mid)) ? above : below) = mid;
    }
    found.push_back(above);
    if (only_first) first = std::min(first, above);
  }
  return found;
}

/// Along an unheld step, where a node first comes to hold more of the body: its wall becomes
/// active, its compliance engages, or it enters the stick branch.
template <int d>
double Driver<d>::first_hold(const ContactPoint& from, const ContactPoint& to) const {
  const auto holding = [](const Kernel& k) {
    return (k.wall_active || k.compliance > 0 ? 1 : 0) + (k.stick ? 1 : 0);
  };
  const std::vector<double> at = crossings(
      from, to, [&](const Kernel& start, const Kernel& k) { return holding(k) > holding(start); },
      true);
  return at.empty() ? std::numeric_limits<double>::infinity()
                    : *std::min_element(at.begin(), at.end());
}

/// Along a step, where each node first crosses a kink of its kernel: the breakpoints of the
/// residual, piecewise smooth in alpha.
template <int d>
std::vector<double> Driver<d>::kinks(const ContactPoint& from, const ContactPoint& to) const {
  return crossings(
      from, to,
      [](const Kernel& start, const Kernel& k) {
        return combinatorial<d>(branch_of(k)) != combinatorial<d>(branch_of(start)) ||
               (k.compliance_slope == 0) != (start.compliance_slope == 0);
      },
      false);
}

/// Step (iv)'s measures of the iteration that moved the state from `before` to `now`.
template <int d>
void Driver<d>::record(Test& test, const ContactPoint& before, const ContactPoint& now,
                       double alpha) {
  double dx2 = std::pow(bulk_.displacement_step(), 2), x2 = std::pow(bulk_.displacement_norm(), 2);
  for (int p = 0; p < m_; ++p) {
    const double w = weight(p);
    const Tan t = tangent_at<d>(now.t, p);
    dx2 += std::pow((now.lambda[p] - before.lambda[p]) / w, 2) +
           squared(Tan((t - tangent_at<d>(before.t, p)) / w));
    x2 += std::pow(now.lambda[p] / w, 2) + squared(Tan(t / w));
  }
  IterationRecord& r = test.record;
  r.residual = now.residual / bulk_.force_scale();
  r.step = std::sqrt(dx2);
  r.increment = r.step / std::max(std::sqrt(x2), 1e-300);
  r.kind = kind_;
  r.merit_ratio = kind_ == 1 ? 0.0 : ratio_;
  result_.history.push_back(r);
  result_.step_length.push_back(alpha);
}

/// After an accepted step: the globalization's bookkeeping, true if the solve must stop (the
/// failure set).
template <int d> bool Driver<d>::stopped(int iteration, double first_residual) {
  const double residual = result_.history.back().residual * bulk_.force_scale();
  memory_.push(residual);
  if (residual < best_) {
    best_ = residual;
    best_at_ = iteration;
  }
  if (!(residual <= kDivergence * std::max(first_residual, bulk_.force_scale()))) {
    fail(NewtonFailure::divergence, "the residual grew to " +
                                        std::to_string(residual / bulk_.force_scale()) +
                                        " of the force scale");
    return true;
  }
  // The thesis's full steps (search=no) stay full steps: a stall is then the stopping test's.
  if (options_.globalize && iteration - best_at_ >= kProgressWindow && !monotone_) {
    monotone_ = true;
    cycles_ = CycleGuard(kCycleWindow);
  }
  return false;
}

/// The result's forces at the last iterate: compliance plus multipliers, or penalty's springs;
/// the failure named if the solve did not converge.
template <int d> void Driver<d>::finish(const ContactPoint& now) {
  // A solve that ends without converging soon after an unheld step that nothing held has
  // drifted: the load's part along a rigid motion is not held (the load beyond the friction
  // bound, the obstacle on the wrong side).
  const int iterations = static_cast<int>(result_.history.size());
  if (!result_.converged && drift_at_ > 0 && iterations - drift_at_ < kProgressWindow &&
      (result_.reason == NewtonFailure::none || result_.reason == NewtonFailure::stagnation ||
       result_.reason == NewtonFailure::cycling)) {
    result_.drift = drift_;
    result_.reason = NewtonFailure::none;
    fail(NewtonFailure::drift,
         "a rigid motion of the body is held by no contact and no friction: the load's part along "
         "it moved the body by " +
             std::to_string(drift_) + " at iteration " + std::to_string(drift_at_) +
             "; check the load against the friction bound and the obstacle's side");
  }
  if (!result_.converged && result_.reason == NewtonFailure::none) {
    if (static_cast<int>(result_.history.size()) > kProgressWindow &&
        static_cast<int>(result_.history.size()) - best_at_ >= kProgressWindow)
      fail(NewtonFailure::stagnation,
           "the residual's least value, " + std::to_string(best_ / bulk_.force_scale()) + ", is " +
               std::to_string(result_.history.size() - best_at_) + " iterations old");
    else
      fail(NewtonFailure::iteration_limit, "no convergence within the iteration limit");
  }
  // A solve that fails with every node that bears a friction bound slipping at it (the counts of
  // the last accepted iteration): the body may be loaded beyond what friction holds. In 3D the
  // slip directions' curvature holds each step, so no unheld step marks the drift (the 3D block
  // under mu1 below its load's ratio). Not added to a drift, which says so, or a divergence.
  if (!result_.converged && friction_ && !result_.history.empty() &&
      result_.reason != NewtonFailure::drift && result_.reason != NewtonFailure::divergence &&
      result_.history.back().stick == 0 && result_.history.back().slip > 0)
    result_.failure += "; every node with a friction bound slips at it: if the tangential load "
                       "exceeds what friction can hold, there is no equilibrium (check the load "
                       "against the friction bound)";
  result_.normal_force.resize(m_);
  result_.tangential_force.resize((d - 1) * m_);
  for (int p = 0; p < m_; ++p) {
    const Tan t = tangent_at<d>(now.t, p);
    const Kernel k = tested(p, now.q_n[p], tangent_at<d>(now.q_t, p), now.lambda[p], t);
    result_.normal_force[p] =
        method_.has_multipliers() ? weight(p) * k.compliance + now.lambda[p] : weight(p) * k.normal;
    set_tangent<d>(result_.tangential_force, p,
                   method_.has_multipliers() ? t : Tan(weight(p) * k.tangential));
  }
}

template <int d> ContactNewtonResult Driver<d>::run(ContactIterate& iterate) {
  start(iterate);
  ContactPoint now = point(iterate.lambda, iterate.t);
  const double first_residual = best_ = now.residual;
  memory_.push(now.residual);
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    Test t = test(now, iterate, one_change_);
    if (cycles_.repeats(combinatorial<d>(t.branch), now.residual)) {
      if (!options_.globalize || !restrict_steps()) {
        fail(NewtonFailure::cycling,
             "the active and stick/slip sets of iteration " + std::to_string(iteration) +
                 " repeat an earlier iteration's without progress" +
                 (options_.globalize ? ", with one change per iteration and monotone steps" : ""));
        break;
      }
      t = test(now, iterate, one_change_);
    }
    // A relaxed step may start a watch (header): the bulk remembers where it starts.
    const bool watchable = options_.globalize && method_.has_multipliers() && !monotone_ &&
                           !one_change_ && !watch_ && !returned_;
    if (watchable) bulk_.checkpoint();
    const Damping damping = damping_;
    const double drift = drift_; // an unheld step searched as any other sets it
    const int drift_at = drift_at_;
    Step step;
    if (!solve(t, now, step)) break;
    ContactPoint next;
    const double alpha = step_length(t, now, step, next);
    if (alpha == 0) {
      bulk_.move(0.0); // back to the last iterate
      break;
    }
    bulk_.restore();
    std::optional<Watch> started;
    if (watchable && kind_ == 0 && next.residual > now.residual)
      started = Watch{now,      iterate, memory_, cycles_,  best_,
                      best_at_, damping, drift,   drift_at, kWatchSteps};
    if (returned_ && kind_ == 0) kind_ = 5;
    returned_ = false;
    record(t, now, next, alpha);
    const double before_step = now.residual;
    now = std::move(next);
    iterate.lambda = now.lambda;
    iterate.t = now.t;
    std::vector<KernelBranch> branch = combinatorial<d>(t.branch);
    // PDAS's statuses settle at a solution, except at a degenerate one (a slip rate or a gap
    // and its force both 0, their branch decided by the rounding): a residual at round-off
    // stands for them (the 3D pad of creep_slip.dat slipping to rest flipped stick and slip at
    // a residual of 1e-16 until the cycle guard stopped it).
    const bool settled =
        !method_.needs_settled_statuses() || branch == iterate.branch || at_round_off(now);
    iterate.branch = std::move(branch);
    const IterationRecord& r = result_.history.back();
    if (r.increment <= options_.eps && r.residual <= options_.eps && settled && bulk_.settled()) {
      result_.converged = true;
      break;
    }
    if (stopped(iteration, first_residual)) break;
    // The watchdog (header): within kWatchSteps steps after a nonmonotone one the merit must
    // fall below where that one started, else the solve returns there, unless the path's rate
    // promises the repayment (one step more, then the same question, kWatchSteps at most).
    // Restricted steps (after a cycle or a stall) lower the merit from where they are, and end
    // the watch.
    if (monotone_ || one_change_) watch_.reset();
    if (watch_) {
      const double start = watch_->before.residual;
      if (sufficient_decrease(now.residual, start, start, 1.0)) {
        watch_.reset();
      } else if (--watch_->left == 0) {
        if (watch_->extended < kWatchSteps && rate_repays(now.residual, before_step, start)) {
          ++watch_->extended;
          watch_->left = 1;
        } else {
          return_to(*watch_, now, iterate);
          watch_.reset();
        }
      }
    }
    if (started) watch_ = std::move(started);
  }
  finish(now);
  return std::move(result_);
}

} // namespace

ContactNewtonOptions newton_options(const ContactSolverParameters& parameters) {
  SIG_VERIFY(parameters.search == "auto" || parameters.search == "yes" || parameters.search == "no",
             "line search '" << parameters.search << "' is unknown; known: auto, yes, no");
  ContactNewtonOptions o;
  o.eps = parameters.eps;
  o.max_iterations = parameters.max_iterations;
  o.globalize = parameters.search != "no";
  return o;
}

bool ContactSetting::has_friction() const {
  return any_friction(law);
}

ContactNewtonResult solve_contact(ContactBulk& bulk, const ContactSetting& setting,
                                  const ContactMethod& method, const ContactNewtonOptions& options,
                                  ContactIterate& iterate) {
  if (bulk.has_tangential() && bulk.tangents() == 2)
    return Driver<3>(bulk, setting, method, options).run(iterate);
  return Driver<2>(bulk, setting, method, options).run(iterate);
}

} // namespace sig
