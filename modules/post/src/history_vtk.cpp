#include "post/history_vtk.hpp"

#include "core/error.hpp"
#include "post/solution_fields.hpp"
#include "post/summary.hpp"

#include <cstdint>

namespace sig {
namespace {

/// The contact pressure of every kept state on the mesh nodes (outputs x nodes, 0 off Gamma3),
/// from the arrays contact_node (1-based) and pressure {outputs, p} of a march with contact;
/// empty when the march had no contact.
std::vector<double> nodal_pressure(const Ds& hist, std::size_t outputs, std::size_t nodes) {
  if (!hist.has("contact_node") || !hist.has("pressure")) return {};
  const std::vector<std::int64_t> contact_node = hist.ints("contact_node");
  const std::vector<double> pressure = hist.reals("pressure");
  const std::vector<std::int64_t>& shape = hist.shape("pressure");
  const std::size_t p = contact_node.size();
  SIG_VERIFY(shape.size() == 2 && static_cast<std::size_t>(shape[0]) == outputs &&
                 static_cast<std::size_t>(shape[1]) == p,
             hist.source << ": array 'pressure' is not " << outputs << " states x " << p
                         << " contact nodes");
  std::vector<double> nodal(outputs * nodes, 0.0);
  for (std::size_t j = 0; j < p; ++j) {
    const std::int64_t node = contact_node[j];
    SIG_VERIFY(node >= 1 && static_cast<std::size_t>(node) <= nodes,
               hist.source << ": contact_node[" << j << "] = " << node << " is not a mesh node (1.."
                           << nodes << ")");
    for (std::size_t s = 0; s < outputs; ++s)
      nodal[s * nodes + static_cast<std::size_t>(node - 1)] = pressure[s * p + j];
  }
  return nodal;
}

} // namespace

std::vector<std::filesystem::path> write_history_vtk(const std::filesystem::path& outdir,
                                                     const std::string& stem, const Mesh& mesh,
                                                     const MaterialTable& materials, const Ds& hist,
                                                     const VtkText& field_data) {
  const std::vector<double> times = hist.reals("output_time");
  const std::vector<double> u = hist.reals("u");
  const std::vector<double> v = hist.reals("v");
  const auto ndof = static_cast<std::size_t>(2 * mesh.num_nodes());
  const std::size_t outputs = times.size();
  for (const char* name : {"u", "v"}) {
    const std::vector<std::int64_t>& shape = hist.shape(name);
    SIG_VERIFY(shape.size() == 2 && static_cast<std::size_t>(shape[0]) == outputs &&
                   static_cast<std::size_t>(shape[1]) == ndof,
               hist.source << ": array '" << name << "' is not " << outputs << " states x " << ndof
                           << " dofs (" << mesh.num_nodes() << " mesh nodes)");
  }
  const auto nodes = static_cast<std::size_t>(mesh.num_nodes());
  const std::vector<double> pressure = nodal_pressure(hist, outputs, nodes);

  return write_vtu_series(outdir, stem, mesh, outputs, [&](std::size_t s) {
    const std::vector<double> u_s(u.begin() + s * ndof, u.begin() + (s + 1) * ndof);
    SolutionFields fields = solution_fields(mesh, u_s, materials, {});
    VtkField velocity{"velocity", 3, {}};
    for (std::size_t i = 0; i < ndof; i += 2)
      velocity.values.insert(velocity.values.end(), {v[s * ndof + i], v[s * ndof + i + 1], 0.0});
    fields.point.push_back(std::move(velocity));
    if (!pressure.empty())
      fields.point.push_back(
          {"contact_pressure", 1,
           std::vector<double>(pressure.begin() + s * nodes, pressure.begin() + (s + 1) * nodes)});
    return VtkState{times[s], std::move(fields.point), std::move(fields.cell), field_data, {}};
  });
}

} // namespace sig
