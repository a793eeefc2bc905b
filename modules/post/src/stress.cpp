#include "post/stress.hpp"

#include "core/error.hpp"

namespace sig {

Eigen::Vector3d triangle_strain(const Mesh& mesh, const std::vector<double>& u, int t) {
  const auto& tri = mesh.triangles[t];
  const double two_area = signed_double_area(mesh, t);
  // Gradient of the barycentric coordinate of vertex i: the rotated opposite edge / (2 area).
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const auto& pj = mesh.nodes[tri[(i + 1) % 3]];
    const auto& pk = mesh.nodes[tri[(i + 2) % 3]];
    const double dx = (pj.y() - pk.y()) / two_area;
    const double dy = (pk.x() - pj.x()) / two_area;
    const double u1 = u[2 * tri[i]];
    const double u2 = u[2 * tri[i] + 1];
    e[0] += u1 * dx;
    e[1] += u2 * dy;
    e[2] += u1 * dy + u2 * dx;
  }
  return e;
}

CellStress cell_stresses(const Mesh& mesh, const std::vector<double>& u,
                         const MaterialTable& materials) {
  SIG_VERIFY(u.size() == 2 * mesh.nodes.size(),
             "displacement holds " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  CellStress out;
  out.stress.reserve(4 * mesh.triangles.size());
  out.von_mises.reserve(mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const Hooke& hooke = materials.of(mesh.subdomain[t]).hooke;
    const Eigen::Vector3d strain = triangle_strain(mesh, u, t);
    const Eigen::Vector3d s = hooke.stress(strain);
    out.stress.insert(out.stress.end(), {s[0], s[1], s[2], hooke.stress33(strain)});
    out.von_mises.push_back(hooke.von_mises(strain));
  }
  return out;
}

} // namespace sig

namespace sig {

double strain_energy(const Mesh& mesh, const std::vector<double>& u,
                     const MaterialTable& materials) {
  SIG_VERIFY(u.size() == 2 * mesh.nodes.size(),
             "displacement holds " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  double energy = 0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const SubdomainMaterial& material = materials.of(mesh.subdomain[t]);
    energy += material.hooke.energy_density(triangle_strain(mesh, u, t)) * 0.5 *
              signed_double_area(mesh, t) * material.thickness;
  }
  return energy;
}

} // namespace sig
