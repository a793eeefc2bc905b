#include "solver/solution_ds.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"

#include <cmath>

namespace sig {

void put_contact_state(Ds& ds, const Eigen::VectorXd& normal, const Eigen::VectorXd& tangential,
                       const std::vector<NormalStatus>& normal_status,
                       const std::vector<FrictionStatus>& friction_status) {
  const auto m = static_cast<std::size_t>(normal.size());
  SIG_VERIFY(static_cast<std::size_t>(tangential.size()) == m && normal_status.size() == m &&
                 friction_status.size() == m,
             "contact state: " << normal.size() << " normal forces, " << tangential.size()
                               << " tangential, " << normal_status.size() << " and "
                               << friction_status.size() << " statuses");
  std::vector<std::int64_t> status(m), normal_code(m), friction_code(m);
  for (std::size_t p = 0; p < m; ++p) {
    status[p] = normal_status[p] != NormalStatus::free ? 1 : 0;
    normal_code[p] = static_cast<std::int64_t>(normal_status[p]);
    friction_code[p] = static_cast<std::int64_t>(friction_status[p]);
  }
  ds.put("multiplier", std::span<const double>(normal.data(), m));
  ds.put("tangential_multiplier", std::span<const double>(tangential.data(), m));
  ds.put("status", std::span<const std::int64_t>(status));
  ds.put("normal_status", std::span<const std::int64_t>(normal_code));
  ds.put("friction_status", std::span<const std::int64_t>(friction_code));
}

void put_history(Ds& ds, const std::vector<IterationRecord>& history) {
  std::vector<std::int64_t> active, entered, left, stick, slip;
  std::vector<double> residual, increment, step_norm;
  for (const IterationRecord& h : history) {
    active.push_back(h.active);
    entered.push_back(h.entered);
    left.push_back(h.left);
    stick.push_back(h.stick);
    slip.push_back(h.slip);
    residual.push_back(h.residual);
    increment.push_back(h.increment);
    step_norm.push_back(h.step);
  }
  ds.put("history_active", std::span<const std::int64_t>(active));
  ds.put("history_entered", std::span<const std::int64_t>(entered));
  ds.put("history_left", std::span<const std::int64_t>(left));
  ds.put("history_stick", std::span<const std::int64_t>(stick));
  ds.put("history_slip", std::span<const std::int64_t>(slip));
  ds.put("history_residual", std::span<const double>(residual));
  ds.put("history_increment", std::span<const double>(increment));
  ds.put("history_step_norm", std::span<const double>(step_norm));
}

void put_convexification(Ds& ds, const ConvexificationResult& loop) {
  std::vector<std::int64_t> inner, changes, wall, compliance, stick, slip;
  std::vector<double> du, dxi, dmu;
  for (const OuterRecord& r : loop.history) {
    inner.push_back(r.inner_iterations);
    changes.push_back(r.status_changes);
    wall.push_back(r.wall);
    compliance.push_back(r.compliance);
    stick.push_back(r.stick);
    slip.push_back(r.slip);
    du.push_back(r.displacement_change);
    dxi.push_back(r.force_change);
    dmu.push_back(r.mu_change);
  }
  ds.put_int("outer_converged", loop.converged ? 1 : 0);
  ds.put_int("outer_iterations", loop.outer_iterations());
  ds.put_int("outer_cycle", loop.cycle);
  ds.put_text("outer_failure", loop.failure);
  ds.put("outer_inner_iterations", std::span<const std::int64_t>(inner));
  ds.put("outer_u_change", std::span<const double>(du));
  ds.put("outer_xi_change", std::span<const double>(dxi));
  ds.put("outer_mu_change", std::span<const double>(dmu));
  ds.put("outer_status_changes", std::span<const std::int64_t>(changes));
  ds.put("outer_wall", std::span<const std::int64_t>(wall));
  ds.put("outer_compliance", std::span<const std::int64_t>(compliance));
  ds.put("outer_stick", std::span<const std::int64_t>(stick));
  ds.put("outer_slip", std::span<const std::int64_t>(slip));
  ds.put("friction_coefficient", std::span<const double>(loop.mu.data(), loop.mu.size()));
}

void write_solution(const std::filesystem::path& path, const StaticSolution& solution,
                    const std::string& method, const std::string& backend,
                    const std::string& title) {
  // A NaN here would flow silently into every report: refuse it where it is made.
  for (Eigen::Index i = 0; i < solution.u.size(); ++i)
    SIG_VERIFY(std::isfinite(solution.u[i]), path.string()
                                                 << ": array 'u' would hold " << solution.u[i]
                                                 << " at dof " << i + 1 << "; nothing written");
  Ds ds("B", title, "sig-solve");
  ds.put("u", std::span<const double>(solution.u.data(), solution.u.size()));
  ds.put_text("method", method);
  ds.put_text("linear", backend);
  ds.put_int("converged", solution.converged ? 1 : 0);
  ds.put_int("iterations", static_cast<std::int64_t>(solution.history.size()));
  ds.put_int("dofs", solution.unknowns);
  ds.put_text("failure", solution.failure);
  if (solution.multiplier.size() > 0) {
    put_contact_state(ds, solution.multiplier, solution.tangential, solution.normal_status,
                      solution.friction_status);
    put_history(ds, solution.history);
  }
  if (solution.convexification) put_convexification(ds, *solution.convexification);
  for (const auto& [phase, seconds] : solution.seconds)
    ds.put_scalar("time_" + phase, seconds);
  write_ds(path, ds);
}

} // namespace sig
