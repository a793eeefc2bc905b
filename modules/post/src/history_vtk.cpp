#include "post/history_vtk.hpp"

#include "core/error.hpp"
#include "post/solution_fields.hpp"
#include "post/summary.hpp"

#include <cstdint>
#include <cstdio>

namespace sig {

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
  verify_finite(u, hist.source, "u");
  verify_finite(v, hist.source, "v");

  std::vector<std::filesystem::path> files{outdir / (stem + ".pvd")};
  std::vector<PvdStep> steps;
  for (std::size_t s = 0; s < outputs; ++s) {
    const std::vector<double> u_s(u.begin() + s * ndof, u.begin() + (s + 1) * ndof);
    SolutionFields fields = solution_fields(mesh, u_s, materials, {});
    VtkField velocity{"velocity", 3, {}};
    for (std::size_t i = 0; i < ndof; i += 2)
      velocity.values.insert(velocity.values.end(), {v[s * ndof + i], v[s * ndof + i + 1], 0.0});
    fields.point.push_back(std::move(velocity));
    char name[32];
    std::snprintf(name, sizeof name, "_%04zu.vtu", s);
    const std::string vtu = stem + name;
    VtkText data = field_data;
    data.emplace_back("time", std::to_string(times[s]));
    write_vtu(outdir / vtu, mesh, fields.point, fields.cell, data);
    steps.push_back({times[s], vtu});
    files.push_back(outdir / vtu);
  }
  write_pvd(files.front(), steps);
  return files;
}

} // namespace sig
