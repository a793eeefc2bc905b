#include "post/summary.hpp"

#include "core/error.hpp"
#include "ds_values.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sig {
namespace {

Json history(const Ds& solution, const std::string& name) {
  return Json::array_of(solution.has(name) ? numbers(solution, name) : std::vector<double>{});
}

/// MUMPS's statistics of the factorization (case.b's mumps_ arrays, stages/solution_ds.cpp):
/// the totals as numbers, the per-rank mumps_rank_ arrays as lists, rank 0 first; none without.
std::optional<Json> mumps_statistics(const Ds& solution) {
  const std::string prefix = "mumps_", per_rank = "rank_";
  Json statistics = Json::object();
  bool any = false;
  for (const auto& array : solution.arrays()) {
    if (!array.name.starts_with(prefix) || array.type != DsType::Float64) continue;
    const std::string what = array.name.substr(prefix.size());
    if (what.starts_with(per_rank))
      statistics.set(what, Json::array_of(solution.reals(array.name)));
    else
      statistics.set(what, solution.scalar(array.name));
    any = true;
  }
  return any ? std::optional<Json>(std::move(statistics)) : std::nullopt;
}

} // namespace

std::vector<std::pair<std::string, double>> gather_times(const std::vector<const Ds*>& sources) {
  std::vector<std::pair<std::string, double>> times;
  for (const Ds* ds : sources) {
    if (ds == nullptr) continue;
    for (const auto& array : ds->arrays()) {
      if (!array.name.starts_with("time_") || array.type != DsType::Float64) continue;
      const std::string phase = array.name.substr(5);
      const double seconds = ds->scalar(array.name);
      const auto it = std::find_if(times.begin(), times.end(),
                                   [&](const auto& entry) { return entry.first == phase; });
      if (it == times.end()) {
        times.emplace_back(phase, seconds);
      } else {
        it->second = seconds;
      }
    }
  }
  return times;
}

Json build_summary(const std::string& title, const Mesh& mesh, const Ds& solution,
                   const std::vector<ContactRow>& contact,
                   const std::vector<std::pair<std::string, double>>& times) {
  const std::string method = solution.text("method");
  const long elements = static_cast<long>(contact.size());
  const long active =
      std::count_if(contact.begin(), contact.end(), [](const ContactRow& r) { return r.contact; });
  Json times_json = Json::object();
  for (const auto& [phase, seconds] : times)
    times_json.set(phase, seconds);

  Json s = Json::object();
  s.set("title", title);
  s.set("method", method);
  s.set("converged", solution.integer("converged") != 0);
  // failure: the name of the reason (cycling, stagnation, divergence, drift, iteration-limit,
  // singular-step), empty when converged; failure_detail: what the solver said.
  s.set("failure",
        solution.has("failure_reason") ? solution.text("failure_reason") : std::string());
  s.set("failure_detail", solution.has("failure") ? solution.text("failure") : std::string());
  if (solution.has("drift")) s.set("drift", solution.scalar("drift"));
  s.set("iterations", static_cast<long>(solution.integer("iterations")));
  s.set("dofs", static_cast<long>(solution.integer("dofs")));
  // The Newton vector holds the displacements and the multipliers the method adds (alm).
  s.set("multipliers", static_cast<long>(solution.integer("dofs")) -
                           static_cast<long>(mesh.dim) * mesh.num_nodes());
  s.set("contact_elements", elements);
  s.set("contact_nodes", active);
  Json normal = Json::object(), friction = Json::object();
  for (NormalStatus status : {NormalStatus::free, NormalStatus::compliance,
                              NormalStatus::unilateral, NormalStatus::held}) {
    const long count = std::count_if(contact.begin(), contact.end(), [status](const ContactRow& r) {
      return r.normal_status == status;
    });
    if (status != NormalStatus::held || count > 0) normal.set(label(status), count); // held: rare
  }
  for (FrictionStatus status : {FrictionStatus::none, FrictionStatus::stick,
                                FrictionStatus::slip_forward, FrictionStatus::slip_backward})
    friction.set(label(status), static_cast<long>(std::count_if(
                                    contact.begin(), contact.end(), [status](const ContactRow& r) {
                                      return r.friction_status == status;
                                    })));
  s.set("normal_status_counts", std::move(normal));
  s.set("friction_status_counts", std::move(friction));
  s.set("nodes", mesh.num_nodes());
  s.set(mesh.dim == 3 ? "tetrahedra" : "triangles", mesh.num_cells());
  s.set("backend", solution.has("linear") ? solution.text("linear") : std::string());
  s.set("ordering", solution.has("ordering") ? solution.text("ordering") : std::string());
  s.set("ranks", solution.has("ranks") ? static_cast<long>(solution.integer("ranks")) : 1L);
  if (std::optional<Json> mumps = mumps_statistics(solution)) s.set("mumps", std::move(*mumps));
  s.set("residual_history", history(solution, "history_residual"));
  s.set("increment_history", history(solution, "history_increment"));
  s.set("step_norm_history", history(solution, "history_step_norm"));
  s.set("active_history", history(solution, "history_active"));
  if (solution.has("history_stick")) {
    s.set("stick_history", history(solution, "history_stick"));
    s.set("slip_history", history(solution, "history_slip"));
  }
  // The convexification loop of a nonmonotone law: the outer count and each inner count.
  if (solution.has("outer_iterations")) {
    Json loop = Json::object();
    loop.set("converged", solution.integer("outer_converged") != 0);
    loop.set("outer_iterations", static_cast<long>(solution.integer("outer_iterations")));
    loop.set("inner_iterations", history(solution, "outer_inner_iterations"));
    loop.set("displacement_change", history(solution, "outer_u_change"));
    loop.set("force_change", history(solution, "outer_xi_change"));
    loop.set("mu_change", history(solution, "outer_mu_change"));
    loop.set("status_changes", history(solution, "outer_status_changes"));
    loop.set("cycle", static_cast<long>(solution.integer("outer_cycle")));
    loop.set("failure", solution.text("outer_failure"));
    s.set("convexification", std::move(loop));
  }
  s.set("times", std::move(times_json));
  return s;
}

Json hertz_json(const HertzData& data, const PressureError& e) {
  Json h = Json::object();
  h.set("b", hertz_half_width(data));
  h.set("p0", hertz_peak_pressure(data));
  h.set("p_max", e.p_max);
  h.set("p_max_rel_error", e.p_max_rel_error);
  h.set("half_width", e.half_width);
  h.set("half_width_error", e.half_width_error);
  h.set("l2_rel_error", e.l2_rel_error);
  return h;
}

} // namespace sig
