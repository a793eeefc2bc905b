#pragma once
// Small elastic bodies for the integrator and stage tests: a unit-density Hooke rectangle
// (interior nodes shifted so that no symmetry helps), its K, consistent and lumped mass, without
// any card.
#include "assembly/pattern.hpp"
#include "assembly/system.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Core>
#include <cmath>

namespace sig::test {

inline Mesh perturbed_rectangle(double lx, double ly, int nx, int ny) {
  Mesh mesh = rectangle(lx, ly, nx, ny);
  const double hx = lx / nx, hy = ly / ny;
  for (Point& x : mesh.nodes) {
    const bool interior =
        x.x() > 1e-12 && x.x() < lx - 1e-12 && x.y() > 1e-12 && x.y() < ly - 1e-12;
    if (!interior) continue;
    // A deterministic shift of at most a fifth of a cell.
    x.x() += 0.2 * hx * std::sin(7.1 * x.x() + 3.3 * x.y());
    x.y() += 0.2 * hy * std::cos(5.3 * x.x() - 2.9 * x.y());
  }
  check_mesh(mesh, "perturbed_rectangle");
  return mesh;
}

inline MaterialTable unit_material(double E = 1.0, double nu = 0.3, double rho = 1.0) {
  SubdomainMaterial m;
  m.subdomain = 1;
  m.hooke.E = E;
  m.hooke.nu = nu;
  m.density = rho;
  return MaterialTable{{m}};
}

/// K, M, M_lumped and zero loads, no Dirichlet dofs.
inline LinearSystem free_body_system(const Mesh& mesh, const MaterialTable& table) {
  const SparsityPattern pattern(mesh);
  LinearSystem s;
  s.K = assemble_stiffness(mesh, table, pattern);
  s.M = assemble_mass(mesh, table, pattern);
  s.M_lumped = assemble_lumped_mass(mesh, table);
  s.f = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  s.dirichlet_values = Eigen::VectorXd(0);
  return s;
}

/// A velocity field with translation, rotation and deformation: v(x) = (0.3 - 0.5 x2 +
/// 0.2 sin(pi x1), -1 + 0.4 x1 + 0.1 x1 x2).
inline Eigen::VectorXd initial_velocity(const Mesh& mesh) {
  Eigen::VectorXd v(2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector2d& x = mesh.nodes[i];
    v(2 * i) = 0.3 - 0.5 * x.y() + 0.2 * std::sin(M_PI * x.x());
    v(2 * i + 1) = -1.0 + 0.4 * x.x() + 0.1 * x.x() * x.y();
  }
  return v;
}

} // namespace sig::test
