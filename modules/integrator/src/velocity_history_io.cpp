#include "integrator/velocity_history_io.hpp"

#include "integrator/history_io.hpp"

#include "assembly/dirichlet.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace sig {

namespace {

/// Per step and node, row 0 the initial state (zeros): {rows, p} row-major.
struct ContactRows {
  std::vector<double> velocity_n, velocity_t, displacement_n, force_n, force_t;
  std::vector<std::int64_t> normal_status, friction_status;
};

ContactRows contact_rows(const VelocityHistory& h, const VelocityHistoryInfo& info) {
  const std::size_t p = info.contact_nodes.size();
  ContactRows r;
  const std::size_t rows = h.steps.size() + 1;
  for (auto* v : {&r.velocity_n, &r.velocity_t, &r.displacement_n, &r.force_n, &r.force_t})
    v->assign(rows * p, 0.0);
  r.normal_status.assign(rows * p, 0);
  r.friction_status.assign(rows * p, 0);
  for (std::size_t s = 0; s < h.steps.size(); ++s) {
    const VelocityStep& step = h.steps[s];
    const std::size_t row = (s + 1) * p;
    SIG_VERIFY(static_cast<std::size_t>(step.normal_velocity.size()) == p &&
                   static_cast<std::size_t>(step.contact.normal_force.size()) == p &&
                   step.contact.normal_status.size() == p,
               "HIST: step " << step.step << " has contact values of another size than its " << p
                             << " contact nodes");
    for (std::size_t i = 0; i < p; ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      r.velocity_n[row + i] = step.normal_velocity[k];
      r.velocity_t[row + i] = step.tangential_velocity[k];
      r.displacement_n[row + i] = r.displacement_n[row - p + i] + info.k * step.normal_velocity[k];
      r.force_n[row + i] = step.contact.normal_force[k];
      r.force_t[row + i] = step.contact.tangential_force[k];
      r.normal_status[row + i] = static_cast<std::int64_t>(step.contact.normal_status[i]);
      r.friction_status[row + i] = static_cast<std::int64_t>(step.contact.friction_status[i]);
    }
  }
  return r;
}

} // namespace

/// sig::Error unless every extra column has a value per step 0 .. the last.
void check_step_columns(const VelocityHistory& h, const VelocityHistoryInfo& info) {
  for (const VelocityHistoryInfo::StepColumn& c : info.step_columns)
    SIG_VERIFY(c.values.size() == h.steps.size() + 1,
               "HIST: column '" << c.name << "' has " << c.values.size() << " values for "
                                << h.steps.size() + 1 << " steps");
}

std::string velocity_steps_csv(const VelocityHistory& history, const VelocityHistoryInfo& info) {
  check_step_columns(history, info);
  std::string csv = velocity_steps_csv_header;
  for (const VelocityHistoryInfo::StepColumn& c : info.step_columns)
    csv += "," + c.name;
  csv += "\n";
  const std::size_t p = info.contact_nodes.size();
  const ContactRows rows = contact_rows(history, info);
  char line[512];
  for (std::size_t s = 0; s < history.steps.size(); ++s) {
    const VelocityStep& step = history.steps[s];
    int count[4] = {0, 0, 0, 0}, friction[4] = {0, 0, 0, 0};
    double max_v = 0, max_u = 0, max_p = 0;
    for (std::size_t i = 0; i < p; ++i) {
      const std::size_t at = (s + 1) * p + i;
      ++count[rows.normal_status[at]];
      ++friction[rows.friction_status[at]];
      max_v = std::max(max_v, rows.velocity_n[at]);
      max_u = std::max(max_u, rows.displacement_n[at]);
      max_p = std::max(max_p, rows.force_n[at] / info.weight[static_cast<Eigen::Index>(i)]);
    }
    std::snprintf(line, sizeof line, "%d,%.17g,%d,%d,%d,%d,%d,%d,%d,%d,%.17g,%.17g,%.17g,%.6g",
                  step.step, step.time, step.converged() ? 1 : 0, step.contact.iterations(),
                  count[0], count[1], count[2], friction[1], friction[2], friction[3], max_v, max_u,
                  max_p, step.seconds);
    csv += line;
    for (const VelocityHistoryInfo::StepColumn& c : info.step_columns) {
      std::snprintf(line, sizeof line, ",%.17g", c.values[s + 1]);
      csv += line;
    }
    csv += "\n";
  }
  return csv;
}

void write_velocity_hist(const std::filesystem::path& path, const VelocityHistory& history,
                         const ReducedSystem& reduced, const VelocityHistoryInfo& info,
                         const std::string& title) {
  Ds ds("HIST", title, "sig-march");
  ds.put_text("scheme", info.scheme);
  ds.put_text("linear", info.backend);
  ds.put_text("method", info.method);
  ds.put_scalar("k", info.k);
  ds.put_scalar("T", info.T);
  ds.put_scalar("time_march", history.seconds);
  ds.put_scalar("time_factorize", info.seconds_factorize);
  ds.put_int("steps", info.steps);
  ds.put_int("output_every", info.output_every);
  ds.put_int("sparse_factorizations", 1);
  ds.put_int("dense_factorizations", info.dense_factorizations);
  std::vector<KeptState> kept;
  for (std::size_t s = 0; s < history.output_step.size(); ++s)
    kept.push_back({history.output_step[s], history.output_step[s] * info.k, &history.output_u[s],
                    &history.output_w[s]});
  put_kept_states(ds, reduced, kept);
  const auto outputs = static_cast<std::int64_t>(kept.size());

  std::vector<std::int64_t> step{0}, iterations{0}, converged{1};
  std::vector<double> time{0.0}, seconds{0.0}, seconds_right_side{0.0}, seconds_contact{0.0};
  for (const VelocityStep& s : history.steps) {
    step.push_back(s.step);
    time.push_back(s.time);
    iterations.push_back(s.contact.iterations());
    converged.push_back(s.converged() ? 1 : 0);
    seconds.push_back(s.seconds);
    seconds_right_side.push_back(s.seconds_right_side);
    seconds_contact.push_back(s.seconds_contact);
  }
  ds.put("step", step);
  ds.put("time", time);
  ds.put("newton_iterations", iterations);
  ds.put("step_converged", converged);
  ds.put("step_seconds", seconds);
  ds.put("step_seconds_right_side", seconds_right_side);
  ds.put("step_seconds_contact", seconds_contact);
  ds.put_int("converged", history.converged ? 1 : 0);
  ds.put_text("failure", history.failure);
  check_step_columns(history, info);
  for (const VelocityHistoryInfo::StepColumn& c : info.step_columns)
    ds.put(c.name, c.values);

  const auto p = static_cast<std::int64_t>(info.contact_nodes.size());
  if (p > 0) {
    put_contact_nodes(ds, info.contact_nodes);
    ds.put("weight", std::span<const double>(info.weight.data(), info.weight.size()));
    const ContactRows rows = contact_rows(history, info);
    const std::vector<std::int64_t> shape{static_cast<std::int64_t>(step.size()), p};
    ds.put("velocity_n", rows.velocity_n, shape);
    ds.put("velocity_t", rows.velocity_t, shape);
    ds.put("displacement_n", rows.displacement_n, shape);
    ds.put("force_n", rows.force_n, shape);
    ds.put("force_t", rows.force_t, shape);
    ds.put("normal_status", rows.normal_status, shape);
    ds.put("friction_status", rows.friction_status, shape);
    std::vector<double> pressure;
    for (int step_kept : history.output_step)
      for (std::int64_t i = 0; i < p; ++i)
        pressure.push_back(rows.force_n[static_cast<std::size_t>(step_kept * p + i)] /
                           info.weight[i]);
    ds.put("pressure", pressure, {outputs, p});
  }
  write_ds(path, ds);
}

} // namespace sig
