#include "post/solution_fields.hpp"

#include "core/error.hpp"
#include "post/stress.hpp"

namespace sig {

SolutionFields solution_fields(const Mesh& mesh, const std::vector<double>& u,
                               const MaterialTable& materials,
                               const std::vector<ContactRow>& contact) {
  const std::size_t n = mesh.nodes.size();
  SIG_VERIFY(u.size() == 2 * n,
             "displacement holds " << u.size() << " values for " << n << " nodes");
  SolutionFields f;
  VtkField displacement{"displacement", 3, std::vector<double>(3 * n, 0.0)};
  for (std::size_t i = 0; i < n; ++i) {
    displacement.values[3 * i] = u[2 * i];
    displacement.values[3 * i + 1] = u[2 * i + 1];
  }
  f.point.push_back(std::move(displacement));
  if (!contact.empty()) {
    VtkField pressure{"contact_pressure", 1, std::vector<double>(n, 0.0)};
    VtkField status{"contact_status", 1, std::vector<double>(n, 0.0), true};
    for (const auto& row : contact) {
      pressure.values[row.node - 1] = row.pressure;
      status.values[row.node - 1] = row.contact ? 1.0 : 0.0;
    }
    f.point.push_back(std::move(pressure));
    f.point.push_back(std::move(status));
  }

  CellStress stress = cell_stresses(mesh, u, materials);
  f.cell.push_back({"stress", 4, std::move(stress.stress)});
  f.cell.push_back({"von_mises", 1, std::move(stress.von_mises)});
  f.cell.push_back(
      {"subdomain", 1, std::vector<double>(mesh.subdomain.begin(), mesh.subdomain.end()), true});
  return f;
}

} // namespace sig
