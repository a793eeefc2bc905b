// The semi-smooth Newton driver of contact_newton.hpp.
#include "solver/contact_newton.hpp"

#include "contact/contact_kernel.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace sig {

namespace {

/// Halvings of the Newton step before the line search gives up on a decrease.
constexpr int kMaxHalvings = 12;
/// A linear bulk searches while its relative residual exceeds this many times eps: near the
/// solution the Newton steps are sound, and round-off (penalty's r ||u|| eps_machine) would make
/// the search stall on residuals it cannot lower.
constexpr double kSearchFar = 1e3;

/// The contact state the kernel and the residual see at the bulk's iterate.
struct ContactPoint {
  Eigen::VectorXd q_n, q_t;  ///< penetration and slip
  Eigen::VectorXd lambda, t; ///< multipliers (nodal forces)
  std::vector<ContactKernel> kernel;
};

class Driver {
public:
  Driver(ContactBulk& bulk, const ContactSetting& setting, const ContactMethod& method,
         const ContactNewtonOptions& options)
      : bulk_(bulk), s_(setting), method_(method), options_(options), m_(setting.size()),
        friction_(bulk.has_tangential()) {}

  ContactNewtonResult run(ContactIterate& iterate);

private:
  ContactBulk& bulk_;
  const ContactSetting& s_;
  const ContactMethod& method_;
  const ContactNewtonOptions& options_;
  const int m_;
  const bool friction_;

  double weight(int p) const { return s_.weight[p]; }

  /// The kernel of node p at (q_n, q_t) with the multiplier lambda the test sees (penalty:
  /// none), in pressures; on the branch `on` if given.
  ContactKernel kernel(int p, double q_n, double q_t, double lambda, double t,
                       const NodeBranch* on = nullptr) const {
    NodeVariables x{q_n, q_t, 0.0, 0.0};
    if (method_.has_multipliers()) {
      x.lambda = lambda / weight(p);
      x.t = t / weight(p);
    }
    const double r = method_.augmentation();
    return on ? contact_kernel(s_.law[p], x, r, r, *on) : contact_kernel(s_.law[p], x, r, r);
  }

  /// The kernels at the bulk's iterate with multipliers (lambda, t); on the branches `on` if
  /// given.
  ContactPoint point(const Eigen::VectorXd& lambda, const Eigen::VectorXd& t,
                     const std::vector<NodeBranch>* on = nullptr) const {
    ContactPoint c{bulk_.penetration(), bulk_.slip(), lambda, t, {}};
    c.kernel.reserve(m_);
    for (int p = 0; p < m_; ++p)
      c.kernel.push_back(kernel(p, c.q_n[p], c.q_t[p], lambda[p], t[p], on ? &(*on)[p] : nullptr));
    return c;
  }

  /// The contact forces of equilibrium: compliance plus multipliers, or penalty's springs.
  void equilibrium_forces(const ContactPoint& c, Eigen::VectorXd& N, Eigen::VectorXd& T) const {
    N.resize(m_);
    T.resize(m_);
    for (int p = 0; p < m_; ++p) {
      const ContactKernel& k = c.kernel[p];
      if (method_.has_multipliers()) {
        N[p] = weight(p) * k.compliance + c.lambda[p];
        T[p] = c.t[p];
      } else {
        N[p] = weight(p) * k.normal;
        T[p] = weight(p) * k.tangential;
      }
    }
  }

  /// ||R|| = ||(equilibrium, w C_n, w C_t)||, absolute.
  double residual(const ContactPoint& c) const {
    Eigen::VectorXd N, T;
    equilibrium_forces(c, N, T);
    double sum = std::pow(bulk_.equilibrium_residual(N, T), 2);
    if (method_.has_multipliers())
      for (int p = 0; p < m_; ++p)
        sum += (weight(p) * c.kernel[p].complementarity).squaredNorm();
    return std::sqrt(sum);
  }

  /// The residual of the system step (iii) linearized, at a point of its line: `c` on the
  /// branches of (ii), whose off-wall rows are the method's condition there, lambda = 0 or
  /// projection's Robin law lambda = (w / c) (q_n - q_n at the step's origin `origin`).
  double held_residual(ContactPoint c, const Eigen::VectorXd& origin) const {
    for (int p = 0; p < m_; ++p)
      if (!c.kernel[p].wall_active)
        c.kernel[p].complementarity[0] -=
            off_wall_stiffness(method_, s_.law[p], weight(p)) * (c.q_n[p] - origin[p]) / weight(p);
    return residual(c);
  }

  /// Step (iii): the condition of node p on the branch of kernel k.
  NodeConditions node_conditions(int p, const ContactKernel& k, double q_n, double q_t) const {
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
    if (k.stick && method_.has_multipliers()) {
      c.tangential.imposed = true;
      c.tangential.value = -q_t;
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
    return c;
  }
};

ContactNewtonResult Driver::run(ContactIterate& iterate) {
  if (iterate.lambda.size() == 0) iterate.lambda = Eigen::VectorXd::Zero(m_);
  if (iterate.t.size() == 0) iterate.t = Eigen::VectorXd::Zero(m_);
  SIG_VERIFY(bulk_.contacts() == m_ && s_.weight.size() == m_ && iterate.lambda.size() == m_ &&
                 iterate.t.size() == m_,
             "contact Newton: the bulk has " << bulk_.contacts() << " contact nodes, the setting "
                                             << m_);
  SIG_VERIFY(friction_ || !s_.has_friction(),
             "contact Newton: a friction law on a bulk without tangential unknowns");
  if (!method_.has_multipliers()) {
    iterate.lambda.setZero();
    iterate.t.setZero();
  }

  ContactNewtonResult result;
  ContactPoint now = point(iterate.lambda, iterate.t);
  double residual_norm = residual(now);
  for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
    // (ii) the branches at the iterate, and (iii)'s conditions on them.
    std::vector<ContactKernel> tested(m_);
    std::vector<NodeBranch> branch(m_);
    std::vector<NodeConditions> conditions(m_);
    IterationRecord record;
    record.wall.resize(m_);
    for (int p = 0; p < m_; ++p) {
      const bool was_on_wall = !iterate.branch.empty() && iterate.branch[p].wall;
      const bool was_inactive = !iterate.branch.empty() && !was_on_wall;
      const ContactKernel& k = tested[p] =
          kernel(p, now.q_n[p], now.q_t[p],
                 method_.tested_multiplier(iterate.lambda[p], was_inactive), iterate.t[p]);
      branch[p] = branch_of(k);
      conditions[p] = node_conditions(p, k, now.q_n[p], now.q_t[p]);
      record.active += k.wall_active ? 1 : 0;
      record.wall[p] = k.wall_active ? 1 : 0;
      if (k.wall_active != was_on_wall) ++(k.wall_active ? record.entered : record.left);
      record.stick += k.stick ? 1 : 0;
      record.slip += k.slip != 0 && k.bound > 0 ? 1 : 0;
    }
    // The statuses of the last test, so a failed iteration still reports where it stood.
    result.normal_status.resize(m_);
    result.friction_status.resize(m_);
    for (int p = 0; p < m_; ++p) {
      result.normal_status[p] = normal_status(tested[p]);
      result.friction_status[p] = friction_status(s_.law[p], tested[p]);
    }

    // (iii) the linear step; its forces give the multipliers at the full step.
    StepSolution step;
    try {
      Eigen::VectorXd N, T;
      equilibrium_forces(now, N, T);
      step = bulk_.solve(conditions, N);
    } catch (const Error& e) {
      result.failure = std::string("the generalized Jacobian could not be factorized: ") +
                       e.what() + " (" + std::to_string(record.active) + " nodes on the wall)";
      break;
    }
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m_), t = Eigen::VectorXd::Zero(m_);
    if (method_.has_multipliers())
      for (int p = 0; p < m_; ++p) {
        const ContactLaw& law = s_.law[p];
        if (conditions[p].normal.imposed) // the reaction, less the compliance at the wall
          lambda[p] = step.normal_force[p] - weight(p) * compliance_pressure(law, law.depth);
        else // projection's Robin force, 0 for the Neumann condition
          lambda[p] = off_wall_stiffness(method_, law, weight(p)) * step.normal_increment[p];
        if (law.has_friction()) t[p] = step.tangential_force[p];
      }

    // Step length (header). A first iteration whose iterate already meets the residual test (a
    // load step starting from the previous one's solution, the new Dirichlet values not in R)
    // seeks no decrease: its trials would not lower it.
    const bool nonlinear = bulk_.nonlinear();
    const bool far = residual_norm > kSearchFar * options_.eps * bulk_.force_scale();
    const bool search = nonlinear || (options_.line_search && far);
    const bool seek_decrease = iteration > 0 || residual_norm > options_.eps * bulk_.force_scale();
    // The merit of the search (header): on a nonlinear bulk, ||R|| on the branches of (ii).
    const std::vector<NodeBranch>* held = nonlinear ? &branch : nullptr;
    const Eigen::VectorXd origin = now.q_n;
    const double start_merit =
        held ? held_residual(point(iterate.lambda, iterate.t, held), origin) : residual_norm;
    double alpha = 1, accepted = 0, accepted_residual = 0, accepted_merit = 0;
    ContactPoint trial;
    for (int h = 0; h <= (search ? kMaxHalvings : 0); ++h, alpha /= 2) {
      if (!bulk_.move(alpha)) continue;
      const Eigen::VectorXd trial_lambda = iterate.lambda + alpha * (lambda - iterate.lambda);
      const Eigen::VectorXd trial_t = iterate.t + alpha * (t - iterate.t);
      trial = point(trial_lambda, trial_t);
      const double trial_residual = residual(trial);
      if (!std::isfinite(trial_residual)) continue; // outside the domain, as an inversion is
      const double merit =
          held ? held_residual(point(trial_lambda, trial_t, held), origin) : trial_residual;
      const bool decreases = merit < start_merit;
      if (accepted == 0 || decreases || (!nonlinear && merit < accepted_merit)) {
        bulk_.keep();
        std::swap(now, trial);
        accepted = alpha;
        accepted_residual = trial_residual;
        accepted_merit = merit;
      }
      if (decreases || !search || (!seek_decrease && accepted > 0)) break;
    }
    if (accepted == 0) {
      result.failure =
          "every step length down to 2^-" + std::to_string(kMaxHalvings) +
          " leaves the bulk's domain (an inverted element) or gives a residual that is not finite";
      bulk_.move(0.0); // back to the last iterate
      break;
    }
    bulk_.restore();

    // (iv) the increment of x = (u, lambda / w, t / w), the residual and the branches.
    double dx2 = std::pow(bulk_.displacement_step(), 2),
           x2 = std::pow(bulk_.displacement_norm(), 2);
    for (int p = 0; p < m_; ++p) {
      const double w = weight(p);
      dx2 += std::pow((now.lambda[p] - iterate.lambda[p]) / w, 2) +
             std::pow((now.t[p] - iterate.t[p]) / w, 2);
      x2 += std::pow(now.lambda[p] / w, 2) + std::pow(now.t[p] / w, 2);
    }
    iterate.lambda = now.lambda;
    iterate.t = now.t;
    residual_norm = accepted_residual;
    record.residual = residual_norm / bulk_.force_scale();
    record.step = std::sqrt(dx2);
    record.increment = record.step / std::max(std::sqrt(x2), 1e-300);
    result.history.push_back(record);
    result.step_length.push_back(accepted);

    const bool settled = !method_.needs_settled_statuses() || branch == iterate.branch;
    iterate.branch = branch;
    if (record.increment <= options_.eps && record.residual <= options_.eps && settled &&
        bulk_.settled()) {
      result.converged = true;
      break;
    }
  }
  if (!result.converged && result.failure.empty())
    result.failure = "no convergence within the iteration limit";
  equilibrium_forces(now, result.normal_force, result.tangential_force);
  return result;
}

} // namespace

ContactNewtonOptions newton_options(const ContactSolverParameters& parameters,
                                    const std::vector<ContactLaw>& laws) {
  SIG_VERIFY(parameters.search == "auto" || parameters.search == "yes" || parameters.search == "no",
             "line search '" << parameters.search << "' is unknown; known: auto, yes, no");
  ContactNewtonOptions o;
  o.eps = parameters.eps;
  o.max_iterations = parameters.max_iterations;
  // Full steps for frictionless Signorini, as the thesis's tables; friction and the compliance
  // laws cycle without a search (a compliance kink on every node near the wall). Penalty's steps
  // are Newton's on piecewise-linear springs, stiff for a large r: a residual search would creep
  // along them; it takes full steps unless asked.
  const bool beyond_signorini = std::any_of(laws.begin(), laws.end(), [](const ContactLaw& l) {
    return l.has_friction() || l.has_compliance();
  });
  o.line_search = parameters.search == "yes" || (parameters.search == "auto" && beyond_signorini &&
                                                 parameters.method != "penalty");
  return o;
}

bool ContactSetting::has_friction() const {
  return any_friction(law);
}

ContactNewtonResult solve_contact(ContactBulk& bulk, const ContactSetting& setting,
                                  const ContactMethod& method, const ContactNewtonOptions& options,
                                  ContactIterate& iterate) {
  return Driver(bulk, setting, method, options).run(iterate);
}

} // namespace sig
