#include "assembly/strain.hpp"

#include "assembly/p1.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"

#include <cmath>

namespace sig {

std::vector<Eigen::Vector3d> element_strains(const Mesh& mesh, const Eigen::VectorXd& u) {
  SIG_VERIFY(u.size() == 2 * mesh.num_nodes(),
             "element_strains: " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  std::vector<Eigen::Vector3d> strains(mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    Vector6d ue;
    for (int i = 0; i < 3; ++i)
      ue.segment<2>(2 * i) = u.segment<2>(2 * mesh.cells[t][i]);
    strains[t] = p1_strain_matrix(p1_gradients(triangle_vertices(mesh, t))) * ue;
  }
  return strains;
}

double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u) {
  return strain_norm(mesh, u, [](int) { return true; });
}

double strain_norm(const Mesh& mesh, const Eigen::VectorXd& u,
                   const std::function<bool(int)>& counts) {
  const std::vector<Eigen::Vector3d> strains = element_strains(mesh, u);
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    if (!counts(t)) continue;
    const Eigen::Vector3d& e = strains[t]; // (e11, e22, 2 e12): eps : eps = e11^2 + e22^2 + 2 e12^2
    sum += 0.5 * std::abs(signed_double_area(mesh, t)) *
           (e[0] * e[0] + e[1] * e[1] + 0.5 * e[2] * e[2]);
  }
  return std::sqrt(sum);
}

std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const MaterialTable& table,
                                              const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector3d> stresses = element_strains(mesh, u);
  for (int t = 0; t < mesh.num_cells(); ++t)
    stresses[t] = table.of(mesh.subdomain[t]).hooke.stress(stresses[t]);
  return stresses;
}

} // namespace sig
