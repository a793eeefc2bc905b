#include "stages/solution_ds.hpp"

#include "core/ds.hpp"
#include "core/ds_columns.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sig {

void put_contact_state(Ds& ds, const Eigen::VectorXd& normal, const Eigen::VectorXd& tangential,
                       const std::vector<NormalStatus>& normal_status,
                       const std::vector<FrictionStatus>& friction_status) {
  const auto m = static_cast<std::size_t>(normal.size());
  // In 3D two tangential components per node, along its tangents t1, t2 (contact_frame).
  const bool pair = m > 0 && static_cast<std::size_t>(tangential.size()) == 2 * m;
  SIG_VERIFY((static_cast<std::size_t>(tangential.size()) == m || pair) &&
                 normal_status.size() == m && friction_status.size() == m,
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
  if (pair)
    ds.put("tangential_multiplier", std::span<const double>(tangential.data(), 2 * m),
           {static_cast<std::int64_t>(m), 2});
  else
    ds.put("tangential_multiplier", std::span<const double>(tangential.data(), m));
  ds.put("status", std::span<const std::int64_t>(status));
  ds.put("normal_status", std::span<const std::int64_t>(normal_code));
  ds.put("friction_status", std::span<const std::int64_t>(friction_code));
}

void put_history(Ds& ds, const std::vector<IterationRecord>& history) {
  put_column(ds, "history_active", history, &IterationRecord::active);
  put_column(ds, "history_entered", history, &IterationRecord::entered);
  put_column(ds, "history_left", history, &IterationRecord::left);
  put_column(ds, "history_stick", history, &IterationRecord::stick);
  put_column(ds, "history_slip", history, &IterationRecord::slip);
  put_column(ds, "history_residual", history, &IterationRecord::residual);
  put_column(ds, "history_increment", history, &IterationRecord::increment);
  put_column(ds, "history_step_norm", history, &IterationRecord::step);
  put_column(ds, "history_kind", history, &IterationRecord::kind);
  // The active sets, one row per iteration, when every iteration has one of the same size.
  const std::size_t m = history.empty() ? 0 : history.front().wall.size();
  if (m == 0 || std::any_of(history.begin(), history.end(),
                            [m](const IterationRecord& r) { return r.wall.size() != m; }))
    return;
  std::vector<std::int64_t> wall;
  wall.reserve(history.size() * m);
  for (const IterationRecord& r : history)
    wall.insert(wall.end(), r.wall.begin(), r.wall.end());
  ds.put("history_wall", wall,
         {static_cast<std::int64_t>(history.size()), static_cast<std::int64_t>(m)});
}

void put_failure_reason(Ds& ds, bool converged, NewtonFailure reason, double drift) {
  if (converged) return;
  ds.put_text("failure_reason",
              name(reason == NewtonFailure::none ? NewtonFailure::iteration_limit : reason));
  if (reason == NewtonFailure::drift) ds.put_scalar("drift", drift);
}

void put_convexification(Ds& ds, const ConvexificationResult& loop) {
  ds.put_int("outer_converged", loop.converged ? 1 : 0);
  ds.put_int("outer_iterations", loop.outer_iterations());
  ds.put_int("outer_cycle", loop.cycle);
  ds.put_text("outer_failure", loop.failure);
  const std::vector<OuterRecord>& outer = loop.history;
  put_column(ds, "outer_inner_iterations", outer, &OuterRecord::inner_iterations);
  put_column(ds, "outer_u_change", outer, &OuterRecord::displacement_change);
  put_column(ds, "outer_xi_change", outer, &OuterRecord::force_change);
  put_column(ds, "outer_mu_change", outer, &OuterRecord::mu_change);
  put_column(ds, "outer_status_changes", outer, &OuterRecord::status_changes);
  put_column(ds, "outer_wall", outer, &OuterRecord::wall);
  put_column(ds, "outer_compliance", outer, &OuterRecord::compliance);
  put_column(ds, "outer_stick", outer, &OuterRecord::stick);
  put_column(ds, "outer_slip", outer, &OuterRecord::slip);
  ds.put("friction_coefficient", std::span<const double>(loop.mu.data(), loop.mu.size()));
}

namespace {

/// MUMPS's statistics of the factorization: the totals as scalars mumps_<what>, the per-rank
/// values (rank 0 first) as arrays mumps_rank_<what>; summary.json takes every mumps_ array.
void put_mumps_statistics(Ds& ds, const MumpsStatistics& m) {
  const std::pair<const char*, double> totals[] = {{"flops", m.flops},
                                                   {"flops_estimate", m.flops_estimate},
                                                   {"factor_entries", m.factor_entries},
                                                   {"factor_space", m.factor_space},
                                                   {"largest_front", m.largest_front},
                                                   {"tree_nodes", m.tree_nodes},
                                                   {"delayed_pivots", m.delayed_pivots},
                                                   {"memory_max_mb", m.memory_max_mb},
                                                   {"memory_total_mb", m.memory_total_mb},
                                                   {"schur_size", m.schur_size},
                                                   {"analysis_seconds", m.analysis_seconds}};
  for (const auto& [what, value] : totals)
    ds.put_scalar(std::string("mumps_") + what, value);
  const std::pair<const char*, const std::vector<double>*> per_rank[] = {
      {"flops", &m.rank_flops},
      {"entries", &m.rank_entries},
      {"memory_mb", &m.rank_memory_mb},
      {"pivots", &m.rank_pivots}};
  for (const auto& [what, values] : per_rank)
    ds.put(std::string("mumps_rank_") + what, std::span<const double>(*values));
}

} // namespace

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
  if (!solution.ordering.empty()) ds.put_text("ordering", solution.ordering);
  ds.put_int("ranks", solution.ranks);
  if (solution.mumps) put_mumps_statistics(ds, *solution.mumps);
  ds.put_int("converged", solution.converged ? 1 : 0);
  ds.put_int("iterations", static_cast<std::int64_t>(solution.history.size()));
  ds.put_int("dofs", solution.unknowns);
  ds.put_text("failure", solution.failure);
  put_failure_reason(ds, solution.converged, solution.reason, solution.drift);
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
