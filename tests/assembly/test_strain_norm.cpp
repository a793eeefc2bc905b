// ||eps(u)||_L2, the norm of V (assembly/strain.hpp), of fields whose strain is known.
#include "assembly/strain.hpp"
#include "core/error.hpp"
#include "mesh/generators.hpp"
#include "mesh/gmsh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>

namespace sig {
namespace {

Eigen::VectorXd nodal(const Mesh& mesh, const std::function<Eigen::Vector2d(Eigen::Vector2d)>& f) {
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u.segment<2>(2 * i) = f(mesh.nodes[i]);
  return u;
}

TEST(StrainNorm, KnownFields) {
  const Mesh mesh = square(1.0, 6);
  // eps11 = 1: ||eps|| = 1 on the unit square; a rotation has none; a pure shear
  // eps12 = 1/2 has eps : eps = 2 (1/2)^2.
  EXPECT_NEAR(strain_norm(mesh, nodal(mesh, [](auto x) { return Eigen::Vector2d(x.x(), 0); })), 1.0,
              1e-14);
  EXPECT_NEAR(strain_norm(mesh, nodal(mesh, [](auto x) { return Eigen::Vector2d(-x.y(), x.x()); })),
              0.0, 1e-14);
  EXPECT_NEAR(
      strain_norm(mesh,
                  nodal(mesh, [](auto x) { return Eigen::Vector2d(0.5 * x.y(), 0.5 * x.x()); })),
      std::sqrt(0.5), 1e-14);
}

// The same norm on tetrahedra (the static 3D solve's convexification loop measures with it): a
// linear field u = H x has the strain sym(H) everywhere, so ||eps||^2 = |sym(H)|^2 vol exactly.
TEST(StrainNorm, KnownFieldsOnTetrahedra) {
  const Mesh mesh = read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" /
                              "gmsh" / "box_v41_ascii.msh"); // the unit cube
  ASSERT_EQ(mesh.dim, 3);
  Eigen::Matrix3d H;
  H << 0.3, -0.2, 0.5, 0.1, -0.4, 0.25, -0.35, 0.15, 0.2;
  Eigen::VectorXd u(3 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u.segment<3>(3 * i) = H * mesh.nodes[i];
  const Eigen::Matrix3d eps = 0.5 * (H + H.transpose());
  EXPECT_NEAR(strain_norm(mesh, u), eps.norm(), 1e-14);
  // A rotation (the skew part alone) strains nothing.
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u.segment<3>(3 * i) = 0.5 * (H - H.transpose()) * mesh.nodes[i];
  EXPECT_NEAR(strain_norm(mesh, u), 0.0, 1e-14);
  EXPECT_THROW(strain_norm(mesh, Eigen::VectorXd::Zero(2 * mesh.num_nodes())), Error);
}

} // namespace
} // namespace sig
