#include "post/history_vtk.hpp"

#include "core/error.hpp"
#include "ds_values.hpp"
#include "post/solution_fields.hpp"
#include "post/summary.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

namespace sig {
namespace {

/// A contact array of a march (one value per contact node of the 1-based array contact_node)
/// spread on the mesh nodes of every kept state (outputs x nodes, 0 off Gamma3). Its shape is
/// {outputs, p}, one row per kept state (pressure), or, with `per_step`, {steps + 1, p}, whose
/// rows output_step are the kept states (the per-step arrays of a march in velocity). Empty when
/// the HIST has no such array.
std::vector<double> nodal_values(const Ds& hist, const std::string& name, std::size_t outputs,
                                 std::size_t nodes, bool per_step = false) {
  if (!hist.has("contact_node") || !hist.has(name)) return {};
  const std::vector<std::int64_t> contact_node = hist.ints("contact_node");
  const std::vector<double> values = numbers(hist, name);
  const std::vector<std::int64_t>& shape = hist.shape(name);
  const std::size_t p = contact_node.size();
  std::vector<std::int64_t> row(outputs);
  for (std::size_t s = 0; s < outputs; ++s)
    row[s] = static_cast<std::int64_t>(s);
  if (per_step) row = hist.ints("output_step");
  const auto rows = shape.empty() ? 0 : shape[0];
  SIG_VERIFY(
      shape.size() == 2 && static_cast<std::size_t>(shape[1]) == p && row.size() == outputs &&
          std::all_of(row.begin(), row.end(), [&](std::int64_t r) { return r >= 0 && r < rows; }),
      hist.source << ": array '" << name << "' is not " << (per_step ? "steps" : "states") << " x "
                  << p << " contact nodes for the " << outputs << " kept states");
  std::vector<double> nodal(outputs * nodes, 0.0);
  for (std::size_t j = 0; j < p; ++j) {
    const std::int64_t node = contact_node[j];
    SIG_VERIFY(node >= 1 && static_cast<std::size_t>(node) <= nodes,
               hist.source << ": contact_node[" << j << "] = " << node << " is not a mesh node (1.."
                           << nodes << ")");
    for (std::size_t s = 0; s < outputs; ++s)
      nodal[s * nodes + static_cast<std::size_t>(node - 1)] =
          values[static_cast<std::size_t>(row[s]) * p + j];
  }
  return nodal;
}

} // namespace

std::vector<std::filesystem::path> write_history_vtk(const std::filesystem::path& outdir,
                                                     const std::string& stem, const Mesh& mesh,
                                                     const MaterialTable& materials, const Ds& hist,
                                                     const VtkText& field_data,
                                                     VtkCompression compression) {
  const std::vector<double> times = hist.reals("output_time");
  const std::vector<double> u = hist.reals("u");
  const std::vector<double> v = hist.reals("v");
  const auto d = static_cast<std::size_t>(mesh.dim);
  const auto ndof = d * static_cast<std::size_t>(mesh.num_nodes());
  const std::size_t outputs = times.size();
  for (const char* name : {"u", "v"}) {
    const std::vector<std::int64_t>& shape = hist.shape(name);
    SIG_VERIFY(shape.size() == 2 && static_cast<std::size_t>(shape[0]) == outputs &&
                   static_cast<std::size_t>(shape[1]) == ndof,
               hist.source << ": array '" << name << "' is not " << outputs << " states x " << ndof
                           << " dofs (" << mesh.num_nodes() << " mesh nodes)");
  }
  const auto nodes = static_cast<std::size_t>(mesh.num_nodes());
  // The contact pressures of every march with contact (stages/history_io.hpp); a march in
  // velocity also has per step the statuses and forces: without tangential_pressure (no
  // friction, or a case.hist written before the one layout) its force_t / weight.
  std::vector<std::pair<std::string, std::vector<double>>> contact;
  contact.emplace_back("contact_pressure", nodal_values(hist, "pressure", outputs, nodes));
  for (const char* status : {"normal_status", "friction_status"})
    contact.emplace_back(status, nodal_values(hist, status, outputs, nodes, true));
  if (hist.has("tangential_pressure")) {
    contact.emplace_back("tangential_pressure",
                         nodal_values(hist, "tangential_pressure", outputs, nodes));
  } else if (hist.has("force_t") && hist.has("weight")) {
    std::vector<double> tangential = nodal_values(hist, "force_t", outputs, nodes, true);
    const std::vector<double> weight = hist.reals("weight");
    const std::vector<std::int64_t> contact_node = hist.ints("contact_node");
    SIG_VERIFY(weight.size() == contact_node.size(),
               hist.source << ": array 'weight' has " << weight.size() << " values for "
                           << contact_node.size() << " contact nodes");
    for (std::size_t s = 0; s < outputs; ++s)
      for (std::size_t j = 0; j < contact_node.size(); ++j)
        tangential[s * nodes + static_cast<std::size_t>(contact_node[j] - 1)] /= weight[j];
    contact.emplace_back("tangential_pressure", std::move(tangential));
  }

  return write_vtu_series(
      outdir, stem, mesh, outputs,
      [&](std::size_t s) {
        const std::vector<double> u_s(u.begin() + s * ndof, u.begin() + (s + 1) * ndof);
        SolutionFields fields = solution_fields(mesh, u_s, materials, {});
        VtkField velocity{"velocity", 3, {}};
        velocity.values.assign(3 * (ndof / d), 0.0); // d components, z = 0 in 2D
        for (std::size_t i = 0; i < ndof; ++i)
          velocity.values[3 * (i / d) + i % d] = v[s * ndof + i];
        fields.point.push_back(std::move(velocity));
        for (const auto& [name, values] : contact)
          if (!values.empty())
            fields.point.push_back({name, 1,
                                    std::vector<double>(values.begin() + s * nodes,
                                                        values.begin() + (s + 1) * nodes)});
        return VtkState{times[s], std::move(fields.point), std::move(fields.cell), field_data, {}};
      },
      compression);
}

} // namespace sig
