#include "post/solution_fields.hpp"

#include "core/error.hpp"
#include "post/stress.hpp"

namespace sig {

void add_contact_fields(SolutionFields& f, std::size_t n, const std::vector<ContactRow>& contact) {
  if (contact.empty()) return;
  // Statuses as their DS codes (contact/contact_status.hpp): normal 0 free, 1 CN, 2 CU;
  // friction 0 none, 1 S=, 2 S+, 3 S-.
  VtkField pressure{"contact_pressure", 1, std::vector<double>(n, 0.0)};
  VtkField status{"contact_status", 1, std::vector<double>(n, 0.0), true};
  VtkField normal{"normal_status", 1, std::vector<double>(n, 0.0), true};
  VtkField friction{"friction_status", 1, std::vector<double>(n, 0.0), true};
  VtkField tangential{"tangential_pressure", 1, std::vector<double>(n, 0.0)};
  for (const auto& row : contact) {
    const std::size_t i = row.node - 1;
    pressure.values[i] = row.pressure;
    status.values[i] = row.contact ? 1.0 : 0.0;
    normal.values[i] = static_cast<double>(row.normal_status);
    friction.values[i] = static_cast<double>(row.friction_status);
    tangential.values[i] = row.tangential_pressure;
  }
  for (VtkField* field : {&pressure, &status, &normal, &friction, &tangential})
    f.point.push_back(std::move(*field));
  if (contact.front().dim != 3) return;
  // 3D: the tangential traction and the slip turn in the tangent plane; their vectors in global
  // axes (the scalars above are their magnitudes) for ParaView's glyphs. The traction is the
  // body's on the obstacle, as contact.csv's tangential_force_1..3, per unit area.
  VtkField traction{"tangential_traction", 3, std::vector<double>(3 * n, 0.0)};
  VtkField slip{"slip", 3, std::vector<double>(3 * n, 0.0)};
  for (const auto& row : contact) {
    const std::size_t i = row.node - 1;
    for (std::size_t c = 0; c < 3; ++c) {
      traction.values[3 * i + c] = row.tangential_force[c] / row.weight;
      slip.values[3 * i + c] = row.slip_vector[c];
    }
  }
  f.point.push_back(std::move(traction));
  f.point.push_back(std::move(slip));
}

SolutionFields solution_fields(const Mesh& mesh, const std::vector<double>& u,
                               const MaterialTable& materials,
                               const std::vector<ContactRow>& contact) {
  if (mesh.dim == 3) return solution_fields_3d(mesh, u, materials, contact);
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
  add_contact_fields(f, n, contact);

  CellStress stress = cell_stresses(mesh, u, materials);
  f.cell.push_back({"stress", 4, std::move(stress.stress)});
  f.cell.push_back({"von_mises", 1, std::move(stress.von_mises)});
  f.cell.push_back(
      {"subdomain", 1, std::vector<double>(mesh.subdomain.begin(), mesh.subdomain.end()), true});
  return f;
}

} // namespace sig
