// The convexification loop of convexification.hpp.
#include "solver/convexification.hpp"

#include "contact/contact_status.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace sig {

namespace {

/// The longest status cycle the loop looks for.
constexpr int kLongestCycle = 16;

/// |v_i|^2 per node of a flat per-node tangential vector, its size checked.
Eigen::VectorXd node_squares(const Eigen::VectorXd& v, int nodes) {
  SIG_VERIFY(nodes > 0 ? v.size() % nodes == 0 && v.size() >= nodes : v.size() == 0,
             "convexification: " << v.size() << " tangential values for " << nodes
                                 << " contact nodes");
  return tangential_squares(v, nodes);
}

/// ||xi||_L2(Gamma3) of nodal forces: sum_i w_i |F_i / w_i|^2 = sum_i |F_i|^2 / w_i, the
/// tangential force T flat with d - 1 components per node.
double traction_norm(const Eigen::VectorXd& N, const Eigen::VectorXd& T,
                     const Eigen::VectorXd& weight) {
  const Eigen::VectorXd t2 = node_squares(T, static_cast<int>(N.size()));
  return std::sqrt(((N.array().square() + t2.array()) / weight.array()).sum());
}

/// The change a relative to the norm b it is a change of; from nothing (b = 0) any change is
/// whole (1), and no change none.
double relative(double a, double b) {
  return b > 0 ? a / b : (a > 0 ? 1.0 : 0.0);
}

using Statuses = std::vector<int>;

Statuses statuses_of(const ContactNewtonResult& r) {
  Statuses s(r.normal_status.size());
  for (std::size_t p = 0; p < s.size(); ++p)
    s[p] = 4 * static_cast<int>(r.normal_status[p]) + static_cast<int>(r.friction_status[p]);
  return s;
}

} // namespace

int status_cycle(const std::vector<std::vector<int>>& seen) {
  const int n = static_cast<int>(seen.size());
  for (int p = 2; p <= kLongestCycle && kCycleRepeats * p <= n; ++p) {
    bool periodic = true, moving = false;
    for (int j = n - (kCycleRepeats - 1) * p; j < n && periodic; ++j)
      periodic = seen[j] == seen[j - p];
    for (int j = n - p + 1; j < n; ++j)
      moving = moving || seen[j] != seen[j - 1];
    if (periodic && moving) return p;
  }
  return 0;
}

bool needs_convexification(const std::vector<ContactLaw>& laws) {
  return std::any_of(laws.begin(), laws.end(),
                     [](const ContactLaw& l) { return l.friction == FrictionLaw::nonmonotone; });
}

ConvexificationResult convexify(ContactBulk& bulk, const ContactSetting& setting,
                                const ContactMethod& method, const ContactNewtonOptions& inner,
                                const ConvexificationOptions& options,
                                const ConvexificationMeasures& measures, ContactIterate& iterate) {
  SIG_VERIFY(options.eps > 0 && options.max_iterations >= 1 && options.relaxation > 0 &&
                 options.relaxation <= 1,
             "convexification: eps " << options.eps << " must be > 0, max_iterations "
                                     << options.max_iterations << " >= 1 and relaxation "
                                     << options.relaxation << " in (0, 1]");
  SIG_VERIFY(static_cast<bool>(measures.displacement),
             "convexification: the displacement measure is missing");
  const int m = setting.size();
  const auto slip = [&] {
    const Eigen::VectorXd r =
        measures.slip ? measures.slip(bulk) : node_squares(bulk.slip(), m).cwiseSqrt();
    SIG_VERIFY(r.size() == m, "convexification: the slip measure has " << r.size() << " values for "
                                                                       << m << " contact nodes");
    return r;
  };
  const auto norm = [&](const Eigen::VectorXd& v) {
    return measures.norm ? measures.norm(v) : v.norm();
  };

  // mu(0): a at rest, b as if slipped far, or as given; the other laws keep theirs.
  ContactSetting frozen = setting;
  for (ContactLaw& law : frozen.law)
    if (law.friction == FrictionLaw::nonmonotone && options.start != ConvexificationStart::given)
      law.mu = options.start == ConvexificationStart::rest ? friction_coefficient(law, 0.0) : law.b;

  ConvexificationResult result;
  Eigen::VectorXd u_before = measures.displacement(bulk), mu_before(m);
  Eigen::VectorXd N_before = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd T_before = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m) * bulk.tangents());
  for (int p = 0; p < m; ++p)
    mu_before[p] = frozen.law[p].mu;
  std::vector<Statuses> seen;
  for (int k = 0; k < options.max_iterations; ++k) {
    ContactNewtonResult solve = solve_contact(bulk, frozen, method, inner, iterate);
    result.inner_history.insert(result.inner_history.end(), solve.history.begin(),
                                solve.history.end());

    OuterRecord record;
    record.inner_iterations = solve.iterations();
    record.inner_converged = solve.converged;
    const Eigen::VectorXd u = measures.displacement(bulk);
    record.displacement_change = relative(norm(u - u_before), norm(u_before));
    record.force_change = relative(traction_norm(solve.normal_force - N_before,
                                                 solve.tangential_force - T_before, frozen.weight),
                                   traction_norm(N_before, T_before, frozen.weight));
    for (int p = 0; p < m; ++p)
      record.mu_change = std::max(record.mu_change, std::abs(frozen.law[p].mu - mu_before[p]));
    seen.push_back(statuses_of(solve));
    for (int p = 0; p < m; ++p) {
      record.wall += solve.normal_status[p] == NormalStatus::unilateral;
      record.compliance += solve.normal_status[p] == NormalStatus::compliance;
      record.stick += solve.friction_status[p] == FrictionStatus::stick;
      record.slip += solve.friction_status[p] == FrictionStatus::slip_forward ||
                     solve.friction_status[p] == FrictionStatus::slip_backward;
      if (k > 0) record.status_changes += seen[k][p] != seen[k - 1][p];
    }
    result.history.push_back(record);
    result.last = std::move(solve);
    const ContactNewtonResult& last = result.last;

    if (!last.converged) {
      result.reason = last.reason;
      result.failure =
          "convex solve " + std::to_string(k + 1) + " did not converge: " + last.failure;
      break;
    }
    if (k >= 1 && record.displacement_change <= options.eps && record.force_change <= options.eps) {
      result.converged = true;
      break;
    }
    // A cycle of the statuses with no contraction left: the fixed point alternates between the
    // same convex problems.
    if (const int p = status_cycle(seen); p > 0) {
      const double earlier = result.history[k - (kCycleRepeats - 1) * p].displacement_change;
      if (!(record.displacement_change < 0.5 * earlier)) {
        result.cycle = p;
        result.reason = NewtonFailure::cycling;
        result.failure = "the statuses cycle with period " + std::to_string(p) + " over " +
                         std::to_string(kCycleRepeats) +
                         " periods and the displacement change no longer falls (" +
                         std::to_string(record.displacement_change) +
                         "): the fixed point does not contract";
        break;
      }
    }

    // The next coefficients: mu(r) at the new slip, relaxed against the present ones.
    u_before = u;
    N_before = last.normal_force;
    T_before = last.tangential_force;
    const Eigen::VectorXd r = slip();
    for (int p = 0; p < m; ++p) {
      ContactLaw& law = frozen.law[p];
      mu_before[p] = law.mu;
      if (law.friction == FrictionLaw::nonmonotone)
        law.mu = options.relaxation * friction_coefficient(law, r[p]) +
                 (1 - options.relaxation) * law.mu;
    }
  }
  if (!result.converged && result.failure.empty()) {
    result.reason = NewtonFailure::iteration_limit;
    result.failure =
        "no convergence within " + std::to_string(options.max_iterations) + " convex solves";
  }
  result.mu.resize(m);
  for (int p = 0; p < m; ++p)
    result.mu[p] = frozen.law[p].mu;
  return result;
}

} // namespace sig
