#include "integrator/history_io.hpp"

#include "assembly/dirichlet.hpp"
#include "core/ds.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace sig {

std::string energy_csv(const std::vector<EnergyRecord>& energy) {
  std::string csv = std::string(energy_csv_header) + "\n";
  char row[256];
  for (const EnergyRecord& r : energy) {
    std::snprintf(row, sizeof row, "%d,%.17g,%.17g,%.17g,%.17g,0,0,0,%d\n", r.step, r.time,
                  r.kinetic, r.elastic, r.total, r.step > 0 ? 1 : 0);
    csv += row;
  }
  return csv;
}

void write_hist(const std::filesystem::path& path, const MarchHistory& history,
                const ReducedSystem& reduced, const TimeParameters& time,
                const std::string& linear_solver, double seconds, const std::string& title) {
  Ds ds("HIST", title, "sig-march");
  ds.put_text("scheme", time.scheme);
  ds.put_text("mass", to_string(time.mass));
  ds.put_text("linear", linear_solver);
  ds.put_scalar("k", time.k);
  ds.put_scalar("T", time.final_time);
  ds.put_scalar("time_march", seconds);
  ds.put_int("steps", time.steps);
  ds.put_int("output_every", time.output_every);
  const auto ndof = static_cast<std::int64_t>(reduced.num_full());
  ds.put_int("ndof", ndof);

  // The kept states on the full dofs: a velocity is zero where the displacement is imposed.
  std::vector<std::int64_t> output_step;
  std::vector<double> output_time, u, v;
  for (const DynamicState& state : history.outputs) {
    output_step.push_back(std::llround(state.time / time.k));
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
  write_ds(path, ds);
}

} // namespace sig
