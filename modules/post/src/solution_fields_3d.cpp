// What a solved 3D static case shows in ParaView (issue 26): the displacement's three
// components and the contact fields at the nodes; on the tetrahedra the stress tensor's six
// components (s11, s22, s33, s23, s13, s12), von Mises and the sub-domain. The strain is the P1
// simplex routine's (assembly/p1_simplex.hpp), the one the stiffness is made of.
#include "assembly/p1_simplex.hpp"
#include "core/error.hpp"
#include "material/hooke.hpp"
#include "post/solution_fields.hpp"

#include <cmath>

namespace sig {
namespace {

/// The Voigt strain (engineering shear) of tetrahedron t.
Eigen::Matrix<double, 6, 1> cell_strain(const Mesh& mesh, const std::vector<double>& u, int t) {
  SimplexVector<3> ue;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      ue(3 * i + c) = u[3 * static_cast<std::size_t>(mesh.cells[t][i]) + c];
  return p1_simplex_strain_matrix<3>(p1_simplex_gradients<3>(simplex_vertices<3>(mesh, t))) * ue;
}

} // namespace

SolutionFields solution_fields_3d(const Mesh& mesh, const std::vector<double>& u,
                                  const MaterialTable& materials,
                                  const std::vector<ContactRow>& contact) {
  const std::size_t n = mesh.nodes.size();
  SIG_VERIFY(mesh.dim == 3 && u.size() == 3 * n,
             "displacement holds " << u.size() << " values for " << n << " nodes in 3D");
  SolutionFields f;
  f.point.push_back({"displacement", 3, u});
  add_contact_fields(f, n, contact);
  VtkField stress{"stress", 6, {}};
  VtkField von_mises{"von_mises", 1, {}};
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const Eigen::Matrix<double, 6, 1> s =
        materials.of(mesh.subdomain[t]).hooke.D3() * cell_strain(mesh, u, t);
    stress.values.insert(stress.values.end(), s.data(), s.data() + 6);
    const double j2 = ((s(0) - s(1)) * (s(0) - s(1)) + (s(1) - s(2)) * (s(1) - s(2)) +
                       (s(2) - s(0)) * (s(2) - s(0))) /
                          6.0 +
                      s(3) * s(3) + s(4) * s(4) + s(5) * s(5);
    von_mises.values.push_back(std::sqrt(3.0 * j2));
  }
  f.cell.push_back(std::move(stress));
  f.cell.push_back(std::move(von_mises));
  f.cell.push_back(
      {"subdomain", 1, std::vector<double>(mesh.subdomain.begin(), mesh.subdomain.end()), true});
  return f;
}

double strain_energy_3d(const Mesh& mesh, const std::vector<double>& u,
                        const MaterialTable& materials) {
  double energy = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const Eigen::Matrix<double, 6, 1> eps = cell_strain(mesh, u, t);
    energy += 0.5 * p1_measure<3>(simplex_vertices<3>(mesh, t)) *
              eps.dot(materials.of(mesh.subdomain[t]).hooke.D3() * eps);
  }
  return energy;
}

} // namespace sig
