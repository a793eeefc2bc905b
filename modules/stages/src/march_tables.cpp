#include "stages/march_tables.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cstdio>

namespace sig {

std::string energy_csv(const MarchHistory& history) {
  std::string csv = std::string(energy_csv_header) + "\n";
  char row[512];
  for (std::size_t s = 0; s < history.steps_done(); ++s) {
    const StepRecord& step = history.steps[s];
    const EnergyRecord& r = step.energy;
    std::snprintf(row, sizeof row,
                  "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  step.step, step.time, r.kinetic, r.elastic, r.total, r.contact_work,
                  r.max_penetration, r.active_nodes, step.iterations, r.interface, r.friction_work,
                  r.wall_work, r.normal_force, r.tangential_force);
    csv += row;
  }
  return csv;
}

std::string steps_csv(const MarchHistory& history, const HistoryInfo& info) {
  const bool contact = !info.contact_nodes.empty();
  std::vector<HistoryInfo::StepColumn> extra;
  if (history.records.energy) {
    const auto column = [&](const char* name, double EnergyRecord::*field) {
      std::vector<double> values;
      for (const StepRecord& s : history.steps)
        values.push_back(s.energy.*field);
      extra.push_back({name, std::move(values)});
    };
    column("kinetic", &EnergyRecord::kinetic);
    column("elastic", &EnergyRecord::elastic);
    column("total", &EnergyRecord::total);
    if (contact) column("interface", &EnergyRecord::interface);
  }
  extra.insert(extra.end(), info.step_columns.begin(), info.step_columns.end());
  std::string csv = steps_csv_header;
  for (const HistoryInfo::StepColumn& c : extra) {
    SIG_VERIFY(c.values.size() == history.steps.size(),
               "steps.csv: column '" << c.name << "' has " << c.values.size() << " values for "
                                     << history.steps.size() << " steps");
    csv += "," + c.name;
  }
  csv += "\n";
  const auto p = static_cast<Eigen::Index>(info.contact_nodes.size());
  Eigen::VectorXd displacement = Eigen::VectorXd::Zero(p); // sum of k velocity_n per node
  char line[512];
  for (std::size_t s = 1; s < history.steps.size(); ++s) {
    const StepRecord& step = history.steps[s];
    const ContactRecord& c = step.contact;
    int count[4] = {0, 0, 0, 0}, friction[4] = {0, 0, 0, 0};
    double max_v = 0, max_u = 0, max_p = 0;
    for (Eigen::Index i = 0; i < p; ++i) {
      displacement[i] += info.k * c.normal_velocity[i];
      ++count[static_cast<int>(c.normal_status[i])];
      ++friction[static_cast<int>(c.friction_status[i])];
      max_v = std::max(max_v, c.normal_velocity[i]);
      max_u = std::max(max_u, displacement[i]);
      max_p = std::max(max_p, c.normal_force[i] / info.weight[i]);
    }
    std::snprintf(line, sizeof line, "%d,%.17g,%d,%d,%d,%d,%d,%d,%d,%d,%.17g,%.17g,%.17g,%.6g",
                  step.step, step.time, step.converged ? 1 : 0, step.iterations, count[0], count[1],
                  count[2], friction[1], friction[2], friction[3], max_v, max_u, max_p,
                  step.seconds.total);
    csv += line;
    for (const HistoryInfo::StepColumn& column : extra) {
      std::snprintf(line, sizeof line, ",%.17g", column.values[s]);
      csv += line;
    }
    csv += "\n";
  }
  return csv;
}

} // namespace sig
