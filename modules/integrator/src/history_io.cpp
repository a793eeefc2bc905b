#include "integrator/history_io.hpp"

#include "assembly/dirichlet.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace sig {

std::string energy_csv(const std::vector<EnergyRecord>& energy) {
  std::string csv = std::string(energy_csv_header) + "\n";
  char row[512];
  for (const EnergyRecord& r : energy) {
    std::snprintf(row, sizeof row,
                  "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  r.step, r.time, r.kinetic, r.elastic, r.total, r.contact_work, r.max_penetration,
                  r.active_nodes, r.newton_iterations, r.interface, r.friction_work, r.wall_work,
                  r.normal_force, r.tangential_force);
    csv += row;
  }
  return csv;
}

namespace {

void put_contact(Ds& ds, const MarchHistory& history, const ContactHistoryInfo& contact,
                 int steps) {
  ds.put_text("strategy", contact.strategy);
  ds.put_scalar("r", contact.r);
  ds.put_scalar("depth", contact.depth);
  const auto p = static_cast<std::int64_t>(contact.nodes.size());
  std::vector<std::int64_t> node;
  for (int i : contact.nodes)
    node.push_back(i + 1);
  ds.put("contact_node", node);
  std::vector<double> pressure;
  for (const Eigen::VectorXd& state : history.output_pressure) {
    SIG_VERIFY(state.size() == p,
               "HIST: a pressure of " << state.size() << " values for " << p << " contact nodes");
    pressure.insert(pressure.end(), state.data(), state.data() + state.size());
  }
  ds.put("pressure", pressure, {static_cast<std::int64_t>(history.output_pressure.size()), p});
  if (!history.output_tangential_pressure.empty()) {
    std::vector<double> tangential;
    for (const Eigen::VectorXd& state : history.output_tangential_pressure)
      tangential.insert(tangential.end(), state.data(), state.data() + state.size());
    ds.put("tangential_pressure", tangential,
           {static_cast<std::int64_t>(history.output_tangential_pressure.size()), p});
  }
  std::vector<std::int64_t> converged(static_cast<std::size_t>(steps) + 1, 0);
  for (const EnergyRecord& r : history.energy)
    converged[static_cast<std::size_t>(r.step)] = 1;
  ds.put("step_converged", converged);
  std::vector<double> work, penetration, interface, friction, wall;
  std::vector<std::int64_t> active, iterations;
  for (const EnergyRecord& r : history.energy) {
    work.push_back(r.contact_work);
    penetration.push_back(r.max_penetration);
    active.push_back(r.active_nodes);
    iterations.push_back(r.newton_iterations);
    interface.push_back(r.interface);
    friction.push_back(r.friction_work);
    wall.push_back(r.wall_work);
  }
  ds.put("contact_work", work);
  ds.put("interface", interface);
  ds.put("friction_work", friction);
  ds.put("wall_work", wall);
  ds.put("max_penetration", penetration);
  ds.put("active_nodes", active);
  ds.put("newton_iterations", iterations);
}

} // namespace

void put_kept_states(Ds& ds, const ReducedSystem& reduced, const std::vector<KeptState>& kept) {
  const auto ndof = static_cast<std::int64_t>(reduced.num_full());
  ds.put_int("ndof", ndof);
  // On the full dofs: a velocity is zero where the displacement is imposed.
  std::vector<std::int64_t> output_step;
  std::vector<double> output_time, u, v;
  for (const KeptState& state : kept) {
    output_step.push_back(state.step);
    output_time.push_back(state.time);
    const Eigen::VectorXd u_full = reduced.expand(*state.u);
    Eigen::VectorXd v_full = Eigen::VectorXd::Zero(reduced.num_full());
    for (int i = 0; i < reduced.num_free(); ++i)
      v_full(reduced.free_dofs[i]) = (*state.v)(i);
    u.insert(u.end(), u_full.data(), u_full.data() + u_full.size());
    v.insert(v.end(), v_full.data(), v_full.data() + v_full.size());
  }
  const auto outputs = static_cast<std::int64_t>(kept.size());
  ds.put("output_step", output_step);
  ds.put("output_time", output_time);
  ds.put("u", u, {outputs, ndof});
  ds.put("v", v, {outputs, ndof});
}

void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const TimeParameters& time,
                const std::string& linear_solver, double seconds, const std::string& title,
                const ContactHistoryInfo* contact, bool hyperelastic) {
  Ds ds("HIST", title, "sig-march");
  ds.put_text("scheme", time.scheme);
  ds.put_text("mass", to_string(time.mass));
  if (hyperelastic) ds.put_text("stress", to_string(time.stress));
  ds.put_text("linear", linear_solver);
  ds.put_scalar("k", time.k);
  ds.put_scalar("T", time.final_time);
  ds.put_scalar("time_march", seconds);
  ds.put_int("steps", time.steps);
  ds.put_int("output_every", time.output_every);
  std::vector<KeptState> kept;
  for (const DynamicState& state : history.outputs)
    kept.push_back({std::llround(state.time / time.k), state.time, &state.u, &state.v});
  put_kept_states(ds, reduced, kept);

  std::vector<std::int64_t> step;
  std::vector<double> t, kinetic, elastic, total, work;
  for (const EnergyRecord& r : history.energy) {
    step.push_back(r.step);
    t.push_back(r.time);
    kinetic.push_back(r.kinetic);
    elastic.push_back(r.elastic);
    total.push_back(r.total);
    work.push_back(r.external_work);
  }
  ds.put("step", step);
  ds.put("time", t);
  ds.put("kinetic", kinetic);
  ds.put("elastic", elastic);
  ds.put("total", total);
  ds.put("external_work", work);
  ds.put_int("converged", history.converged ? 1 : 0);
  ds.put_text("failure", history.failure);
  if (contact) put_contact(ds, history, *contact, time.steps);
  write_ds(path, ds);
}

} // namespace sig
