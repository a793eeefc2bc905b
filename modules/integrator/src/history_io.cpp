#include "integrator/history_io.hpp"

#include "assembly/dirichlet.hpp"
#include "core/ds.hpp"
#include "core/ds_columns.hpp"
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

/// Array `name` {states, p}: the states one after the other, each of p values.
void put_rows(Ds& ds, const std::string& name, const std::vector<Eigen::VectorXd>& states,
              std::int64_t p) {
  std::vector<double> rows;
  for (const Eigen::VectorXd& state : states) {
    SIG_VERIFY(state.size() == p, "HIST: a " << name << " of " << state.size() << " values for "
                                             << p << " contact nodes");
    rows.insert(rows.end(), state.data(), state.data() + state.size());
  }
  ds.put(name, rows, {static_cast<std::int64_t>(states.size()), p});
}

void put_contact(Ds& ds, const MarchHistory& history, const ContactHistoryInfo& contact,
                 int steps) {
  ds.put_text("strategy", contact.strategy);
  ds.put_scalar("r", contact.r);
  ds.put_scalar("depth", contact.depth);
  put_contact_nodes(ds, contact.nodes);
  const auto p = static_cast<std::int64_t>(contact.nodes.size());
  put_rows(ds, "pressure", history.output_pressure, p);
  if (!history.output_tangential_pressure.empty())
    put_rows(ds, "tangential_pressure", history.output_tangential_pressure, p);
  std::vector<std::int64_t> converged(static_cast<std::size_t>(steps) + 1, 0);
  for (const EnergyRecord& r : history.energy)
    converged[static_cast<std::size_t>(r.step)] = 1;
  ds.put("step_converged", converged);
  put_column(ds, "contact_work", history.energy, &EnergyRecord::contact_work);
  put_column(ds, "interface", history.energy, &EnergyRecord::interface);
  put_column(ds, "friction_work", history.energy, &EnergyRecord::friction_work);
  put_column(ds, "wall_work", history.energy, &EnergyRecord::wall_work);
  put_column(ds, "max_penetration", history.energy, &EnergyRecord::max_penetration);
  put_column(ds, "active_nodes", history.energy, &EnergyRecord::active_nodes);
  put_column(ds, "newton_iterations", history.energy, &EnergyRecord::newton_iterations);
}

} // namespace

void put_contact_nodes(Ds& ds, const std::vector<int>& nodes) {
  std::vector<std::int64_t> node;
  for (int i : nodes)
    node.push_back(i + 1);
  ds.put("contact_node", node);
}

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

  put_column(ds, "step", history.energy, &EnergyRecord::step);
  put_column(ds, "time", history.energy, &EnergyRecord::time);
  put_column(ds, "kinetic", history.energy, &EnergyRecord::kinetic);
  put_column(ds, "elastic", history.energy, &EnergyRecord::elastic);
  put_column(ds, "total", history.energy, &EnergyRecord::total);
  put_column(ds, "external_work", history.energy, &EnergyRecord::external_work);
  ds.put_int("converged", history.converged ? 1 : 0);
  ds.put_text("failure", history.failure);
  if (contact) put_contact(ds, history, *contact, time.steps);
  write_ds(path, ds);
}

} // namespace sig
