#include "post/stress.hpp"

#include "core/error.hpp"
#include "material/hyperelastic.hpp"

#include <Eigen/LU>
#include <cmath>

namespace sig {

Eigen::Vector3d triangle_strain(const Mesh& mesh, const std::vector<double>& u, int t) {
  const auto& tri = mesh.cells[t];
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

namespace {

/// F = I + grad u of triangle t; the strain (e11, e22, 2 e12) holds the same gradient.
Eigen::Matrix2d deformation_gradient(const Mesh& mesh, const std::vector<double>& u, int t) {
  const auto& tri = mesh.cells[t];
  const double two_area = signed_double_area(mesh, t);
  Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
  for (int i = 0; i < 3; ++i) {
    const auto& pj = mesh.nodes[tri[(i + 1) % 3]];
    const auto& pk = mesh.nodes[tri[(i + 2) % 3]];
    const Eigen::Vector2d gradient((pj.y() - pk.y()) / two_area, (pk.x() - pj.x()) / two_area);
    F += Eigen::Vector2d(u[2 * tri[i]], u[2 * tri[i] + 1]) * gradient.transpose();
  }
  return F;
}

} // namespace

CellStress cell_stresses(const Mesh& mesh, const std::vector<double>& u,
                         const MaterialTable& materials) {
  SIG_VERIFY(u.size() == 2 * mesh.nodes.size(),
             "displacement holds " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  CellStress out;
  out.stress.reserve(4 * mesh.cells.size());
  out.von_mises.reserve(mesh.cells.size());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = materials.of(mesh.subdomain[t]);
    if (material.hyperelastic) {
      // Cauchy stress sigma = P F^T / J of the large-deformation law. The 2D laws return the
      // in-plane P only, so s33 is not available: written 0, and von Mises is that of the
      // in-plane Cauchy stress (plane-stress formula).
      const Eigen::Matrix2d F = deformation_gradient(mesh, u, t);
      const HyperelasticResponse r = material.hyperelastic->response(F);
      const Eigen::Matrix2d sigma = r.stress * F.transpose() / (F.determinant() * r.stretch33);
      out.stress.insert(out.stress.end(), {sigma(0, 0), sigma(1, 1), sigma(0, 1), 0.0});
      out.von_mises.push_back(von_mises_stress(sigma(0, 0), sigma(1, 1), sigma(0, 1), 0.0));
      continue;
    }
    const Hooke& hooke = material.hooke;
    const Eigen::Vector3d strain = triangle_strain(mesh, u, t);
    const Eigen::Vector3d s = hooke.stress(strain);
    const double s33 = hooke.stress33(strain);
    out.stress.insert(out.stress.end(), {s[0], s[1], s[2], s33});
    out.von_mises.push_back(von_mises_stress(s[0], s[1], s[2], s33));
  }
  return out;
}

double strain_energy(const Mesh& mesh, const std::vector<double>& u,
                     const MaterialTable& materials) {
  SIG_VERIFY(u.size() == 2 * mesh.nodes.size(),
             "displacement holds " << u.size() << " values for " << mesh.num_nodes() << " nodes");
  double energy = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& material = materials.of(mesh.subdomain[t]);
    const double density = material.hyperelastic
                               ? material.hyperelastic->energy(deformation_gradient(mesh, u, t))
                               : material.hooke.energy_density(triangle_strain(mesh, u, t));
    energy += density * 0.5 * signed_double_area(mesh, t) * material.thickness;
  }
  return energy;
}

} // namespace sig
