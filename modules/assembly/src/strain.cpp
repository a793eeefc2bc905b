#include "assembly/strain.hpp"

#include "assembly/p1.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

namespace sig {

std::vector<Eigen::Vector3d> element_strains(const Mesh& mesh, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "element_strains: " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  std::vector<Eigen::Vector3d> strains(mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    Vector6d ue;
    for (int i = 0; i < 3; ++i)
      ue.segment<2>(2 * i) = u.segment<2>(2 * mesh.triangles[t][i]);
    strains[t] = p1_strain_matrix(p1_gradients(triangle_vertices(mesh, t))) * ue;
  }
  return strains;
}

std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const MaterialTable& table,
                                              const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> stresses = element_strains(mesh, u);
  for (int t = 0; t < mesh.num_triangles(); ++t)
    stresses[t] = table.of(mesh.subdomain[t]).hooke.stress(stresses[t]);
  return stresses;
}

} // namespace sig
