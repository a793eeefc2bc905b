#include "stages/history_io.hpp"

#include "assembly/dirichlet.hpp"
#include "core/ds.hpp"
#include "core/ds_columns.hpp"
#include "core/error.hpp"
#include "solver/contact_bulk.hpp"

#include <cstdint>

namespace sig {

namespace {

void put_kept_states(Ds& ds, const MarchHistory& history, const ReducedSystem& reduced) {
  const auto ndof = static_cast<std::int64_t>(reduced.num_full());
  ds.put_int("ndof", ndof);
  // On the full dofs: a velocity is zero where the displacement is imposed.
  std::vector<std::int64_t> output_step(history.output_step.begin(), history.output_step.end());
  std::vector<double> output_time, u, v;
  for (const DynamicState& state : history.outputs) {
    output_time.push_back(state.time);
    const Eigen::VectorXd u_full = reduced.expand(state.u);
    Eigen::VectorXd v_full = Eigen::VectorXd::Zero(reduced.num_full());
    for (int i = 0; i < reduced.num_free(); ++i)
      v_full(reduced.free_dofs[i]) = state.v(i);
    u.insert(u.end(), u_full.data(), u_full.data() + u_full.size());
    v.insert(v.end(), v_full.data(), v_full.data() + v_full.size());
  }
  const auto outputs = static_cast<std::int64_t>(history.outputs.size());
  ds.put("output_step", output_step);
  ds.put("output_time", output_time);
  ds.put("u", u, {outputs, ndof});
  ds.put("v", v, {outputs, ndof});
}

void put_energy(Ds& ds, const MarchHistory& history, bool contact) {
  const auto& steps = history.steps;
  const auto column = [&](const char* name, auto field) {
    put_column(ds, name, steps, [&](const StepRecord& s) { return std::invoke(field, s.energy); });
  };
  if (history.records.energy) {
    column("kinetic", &EnergyRecord::kinetic);
    column("elastic", &EnergyRecord::elastic);
    column("total", &EnergyRecord::total);
    if (contact) column("interface", &EnergyRecord::interface);
  }
  if (history.records.balance) {
    column("external_work", &EnergyRecord::external_work);
    if (contact) {
      column("contact_work", &EnergyRecord::contact_work);
      column("friction_work", &EnergyRecord::friction_work);
      column("wall_work", &EnergyRecord::wall_work);
      column("max_penetration", &EnergyRecord::max_penetration);
      column("active_nodes", &EnergyRecord::active_nodes);
    }
  }
}

/// Array `name` {rows, p}, or {rows, p, c} with c > 1 components a node: `values` of each row,
/// of c p values (node i's at c i .. c i + c - 1).
void put_rows(Ds& ds, const std::string& name, const std::vector<const Eigen::VectorXd*>& rows,
              std::int64_t p, std::int64_t c = 1) {
  std::vector<double> values;
  for (const Eigen::VectorXd* row : rows) {
    SIG_VERIFY(row->size() == c * p, "HIST: a " << name << " of " << row->size() << " values for "
                                                << p << " contact nodes of " << c << " components");
    values.insert(values.end(), row->data(), row->data() + row->size());
  }
  std::vector<std::int64_t> shape{static_cast<std::int64_t>(rows.size()), p};
  if (c > 1) shape.push_back(c);
  ds.put(name, values, shape);
}

/// Per node the magnitude of the tangential force T (flat, d - 1 components a node): itself in
/// 2D (signed), |T| in the tangent plane in 3D.
Eigen::VectorXd tangential_per_node(const Eigen::VectorXd& T, Eigen::Index p) {
  if (T.size() == p) return T;
  SIG_VERIFY(T.size() == 2 * p, "HIST: a tangential force of " << T.size() << " components for "
                                                               << p << " contact nodes");
  return tangential_squares(T, p).cwiseSqrt();
}

/// The contact forces per kept state, divided by the weights: pressure and, with friction,
/// tangential_pressure (3D: the magnitude in the tangent plane).
void put_kept_pressures(Ds& ds, const MarchHistory& history, const HistoryInfo& info) {
  const auto p = static_cast<std::int64_t>(info.contact_nodes.size());
  std::vector<Eigen::VectorXd> normal, tangential;
  for (int step : history.output_step) {
    const ContactRecord& c = history.steps[static_cast<std::size_t>(step)].contact;
    normal.push_back(c.normal_force.cwiseQuotient(info.weight));
    if (info.friction)
      tangential.push_back(tangential_per_node(c.tangential_force, p).cwiseQuotient(info.weight));
  }
  const auto pointers = [](const std::vector<Eigen::VectorXd>& rows) {
    std::vector<const Eigen::VectorXd*> out;
    for (const Eigen::VectorXd& row : rows)
      out.push_back(&row);
    return out;
  };
  put_rows(ds, "pressure", pointers(normal), p);
  if (info.friction) put_rows(ds, "tangential_pressure", pointers(tangential), p);
}

/// The contact values of every step (the marches in velocity).
void put_contact_per_step(Ds& ds, const MarchHistory& history, const HistoryInfo& info) {
  const auto p = static_cast<std::int64_t>(info.contact_nodes.size());
  const auto rows = static_cast<std::int64_t>(history.steps.size());
  // The tangential values have d - 1 components a node with friction (ContactRecord), the
  // layout of the first row: {rows, p} in 2D and frictionless, {rows, p, 2} in 3D with friction.
  const std::int64_t tangents =
      p > 0 && rows > 0 ? history.steps.front().contact.tangential_force.size() / p : 1;
  const auto column = [&](const char* name, Eigen::VectorXd ContactRecord::*field,
                          std::int64_t components) {
    std::vector<const Eigen::VectorXd*> values;
    for (const StepRecord& s : history.steps)
      values.push_back(&(s.contact.*field));
    put_rows(ds, name, values, p, components);
  };
  column("velocity_n", &ContactRecord::normal_velocity, 1);
  column("velocity_t", &ContactRecord::tangential_velocity, tangents);
  std::vector<double> displacement(static_cast<std::size_t>(rows * p), 0.0);
  std::vector<std::int64_t> normal_status, friction_status;
  for (std::int64_t s = 0; s < rows; ++s) {
    const ContactRecord& c = history.steps[static_cast<std::size_t>(s)].contact;
    SIG_VERIFY(static_cast<std::int64_t>(c.normal_status.size()) == p &&
                   static_cast<std::int64_t>(c.friction_status.size()) == p,
               "HIST: step " << s << " has statuses of another size than its " << p
                             << " contact nodes");
    for (std::int64_t i = 0; i < p; ++i) {
      normal_status.push_back(static_cast<std::int64_t>(c.normal_status[i]));
      friction_status.push_back(static_cast<std::int64_t>(c.friction_status[i]));
      if (s > 0)
        displacement[s * p + i] = displacement[(s - 1) * p + i] + info.k * c.normal_velocity[i];
    }
  }
  ds.put("displacement_n", displacement, {rows, p});
  column("force_n", &ContactRecord::normal_force, 1);
  column("force_t", &ContactRecord::tangential_force, tangents);
  ds.put("normal_status", normal_status, {rows, p});
  ds.put("friction_status", friction_status, {rows, p});
}

} // namespace

void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const HistoryInfo& info, const std::string& title) {
  Ds ds("HIST", title, "sig-march");
  ds.put_text("scheme", info.scheme);
  if (!info.mass.empty()) ds.put_text("mass", info.mass);
  if (!info.stress.empty()) ds.put_text("stress", info.stress);
  ds.put_text("linear", info.linear);
  if (!info.ordering.empty()) ds.put_text("ordering", info.ordering);
  ds.put_int("ranks", info.ranks);
  if (info.setup) ds.put_text("method", info.setup->method);
  ds.put_scalar("k", info.k);
  ds.put_scalar("T", info.T);
  ds.put_scalar("time_march", info.seconds);
  if (info.setup) ds.put_scalar("time_factorize", info.setup->seconds_factorize);
  ds.put_int("steps", info.steps);
  ds.put_int("output_every", info.output_every);
  if (info.setup) {
    ds.put_int("sparse_factorizations", 1);
    ds.put_int("dense_factorizations", info.setup->dense_factorizations);
  }
  put_kept_states(ds, history, reduced);

  // Per step.
  const std::vector<StepRecord>& steps = history.steps;
  put_column(ds, "step", steps, &StepRecord::step);
  put_column(ds, "time", steps, &StepRecord::time);
  put_column(ds, "newton_iterations", steps, &StepRecord::iterations);
  put_column(ds, "step_converged", steps, &StepRecord::converged);
  put_column(ds, "step_seconds", steps, [](const StepRecord& s) { return s.seconds.total; });
  if (info.setup) {
    put_column(ds, "step_seconds_right_side", steps,
               [](const StepRecord& s) { return s.seconds.right_side; });
    put_column(ds, "step_seconds_contact", steps,
               [](const StepRecord& s) { return s.seconds.contact; });
  }
  ds.put_int("converged", history.converged ? 1 : 0);
  ds.put_text("failure", history.failure);
  const bool contact = !info.contact_nodes.empty();
  put_energy(ds, history, contact);
  for (const HistoryInfo::StepColumn& c : info.step_columns) {
    SIG_VERIFY(c.values.size() == steps.size(), "HIST: column '"
                                                    << c.name << "' has " << c.values.size()
                                                    << " values for " << steps.size() << " steps");
    ds.put(c.name, c.values);
  }

  if (contact) {
    std::vector<std::int64_t> node;
    for (int i : info.contact_nodes)
      node.push_back(i + 1);
    ds.put("contact_node", node);
    ds.put("weight", std::span<const double>(info.weight.data(), info.weight.size()));
    if (info.strategy) {
      ds.put_text("strategy", info.strategy->strategy);
      ds.put_scalar("r", info.strategy->r);
      ds.put_scalar("depth", info.strategy->depth);
    }
    put_kept_pressures(ds, history, info);
    if (history.records.contact_per_step) put_contact_per_step(ds, history, info);
  }
  write_ds(path, ds);
}

} // namespace sig
