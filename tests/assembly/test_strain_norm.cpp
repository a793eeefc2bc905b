// ||eps(u)||_L2, the norm of V (assembly/strain.hpp), of fields whose strain is known.
#include "assembly/strain.hpp"
#include "mesh/generators.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

} // namespace
} // namespace sig
