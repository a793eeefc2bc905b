#include "post/load_step_vtk.hpp"

#include "core/error.hpp"
#include "post/contact_table.hpp"
#include "post/solution_fields.hpp"
#include "post/summary.hpp"

#include <cstdint>

namespace sig {

bool has_load_step_states(const Ds& solution) {
  return solution.has("step_u");
}

std::size_t load_step_count(const Ds& solution, const Mesh& mesh) {
  const std::vector<std::int64_t>& shape = solution.shape("step_u");
  const auto ndof = static_cast<std::int64_t>(2 * mesh.num_nodes());
  SIG_VERIFY(shape.size() == 2 && shape[1] == ndof,
             solution.source << ": array 'step_u' is not states x " << ndof << " dofs ("
                             << mesh.num_nodes() << " mesh nodes)");
  const auto rows = static_cast<std::size_t>(shape[0]);
  SIG_VERIFY(rows <= solution.reals("step_load").size(),
             solution.source << ": array 'step_u' holds " << rows << " states for "
                             << solution.reals("step_load").size() << " load steps");
  return rows;
}

namespace {

/// Row `row` of the {rows, width} array `values`.
template <class T>
std::vector<T> row_of(const std::vector<T>& values, std::size_t row, std::size_t width) {
  return {values.begin() + row * width, values.begin() + (row + 1) * width};
}

} // namespace

std::vector<std::filesystem::path>
write_load_step_vtk(const std::filesystem::path& outdir, const std::string& stem, const Mesh& mesh,
                    const MaterialTable& materials, const Ds& solution, const Ds* cont,
                    const VtkText& field_data, VtkCompression compression) {
  const std::size_t states = load_step_count(solution, mesh);
  const std::vector<double> load = solution.reals("step_load");
  const std::vector<double> u = solution.reals("step_u");
  const auto ndof = static_cast<std::size_t>(2 * mesh.num_nodes());

  // With contact, each state is joined with case.cont exactly as the final state is
  // (contact_rows), through a one-state DS "B" holding that step's arrays.
  // Large deformation is frictionless: the states carry no tangential force.
  std::vector<double> multiplier;
  std::vector<std::int64_t> status;
  std::size_t m = 0;
  if (cont != nullptr) {
    multiplier = solution.reals("step_multiplier");
    status = solution.ints("step_normal_status");
    m = cont->ints("node").size();
    for (const char* name : {"step_multiplier", "step_normal_status"}) {
      const std::vector<std::int64_t>& shape = solution.shape(name);
      SIG_VERIFY(shape.size() == 2 && static_cast<std::size_t>(shape[0]) == states &&
                     static_cast<std::size_t>(shape[1]) == m,
                 solution.source << ": array '" << name << "' is not " << states << " states x "
                                 << m << " contact elements");
    }
  }

  return write_vtu_series(
      outdir, stem, mesh, states,
      [&](std::size_t s) {
        Ds state("B", "load step " + std::to_string(s + 1), "sig-post");
        state.source = solution.source + " (load step " + std::to_string(s + 1) + ")";
        state.put("u", row_of(u, s, ndof));
        std::vector<ContactRow> contact;
        if (cont != nullptr) {
          state.put("multiplier", row_of(multiplier, s, m));
          state.put("normal_status", row_of(status, s, m));
          state.put("tangential_multiplier", std::vector<double>(m, 0.0));
          state.put("friction_status", std::vector<std::int64_t>(m, 0));
          contact = contact_rows(mesh, *cont, state);
        }
        SolutionFields fields = solution_fields(mesh, state.reals("u"), materials, contact);
        VtkState vtk{load[s],
                     std::move(fields.point),
                     std::move(fields.cell),
                     field_data,
                     {{"load_step", static_cast<double>(s + 1)}, {"load_factor", load[s]}}};
        return vtk;
      },
      compression);
}

} // namespace sig
