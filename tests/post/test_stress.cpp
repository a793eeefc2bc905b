// Stress for ParaView: exact on affine displacement fields (P1 reproduces them), Hooke's law
// written out independently of the material module, rigid motions stress-free.
#include "post/stress.hpp"

#include "material/saint_venant_kirchhoff.hpp"

#include "core/error.hpp"
#include "post_test_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sig {
namespace {

// u(x) = G x + c on every node.
std::vector<double> affine(const Mesh& mesh, const Eigen::Matrix2d& G, const Eigen::Vector2d& c) {
  std::vector<double> u;
  for (const auto& p : mesh.nodes) {
    const Eigen::Vector2d v = G * p + c;
    u.push_back(v.x());
    u.push_back(v.y());
  }
  return u;
}

MaterialTable two_materials() {
  MaterialTable table;
  SubdomainMaterial strain;
  strain.subdomain = 1;
  strain.hooke = {200.0, 0.3, PlaneMode::strain};
  SubdomainMaterial stress;
  stress.subdomain = 2;
  stress.hooke = {100.0, 0.25, PlaneMode::stress};
  table.entries = {strain, stress};
  return table;
}

TEST(Stress, AffineFieldGivesItsStrainOnEveryTriangle) {
  const Mesh mesh = test::small_mesh();
  Eigen::Matrix2d G;
  G << 0.01, 0.003, -0.002, -0.02;
  const auto u = affine(mesh, G, {0.5, -0.25});
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const Eigen::Vector3d e = triangle_strain(mesh, u, t);
    EXPECT_NEAR(e[0], 0.01, 1e-15);
    EXPECT_NEAR(e[1], -0.02, 1e-15);
    EXPECT_NEAR(e[2], 0.003 - 0.002, 1e-15);
  }
}

TEST(Stress, RigidMotionIsStressFree) {
  const Mesh mesh = test::small_mesh();
  Eigen::Matrix2d W; // infinitesimal rotation
  W << 0, -1e-3, 1e-3, 0;
  const CellStress s = cell_stresses(mesh, affine(mesh, W, {3, 4}), two_materials());
  for (double v : s.stress)
    EXPECT_NEAR(v, 0.0, 1e-12);
  for (double v : s.von_mises)
    EXPECT_NEAR(v, 0.0, 1e-12);
}

TEST(Stress, HookeInPlaneStrainAndPlaneStress) {
  const Mesh mesh = test::small_mesh();
  Eigen::Matrix2d G;
  G << 1e-3, 2e-3, 0, -5e-4; // e11 = 1e-3, e22 = -5e-4, 2 e12 = 2e-3
  const CellStress s = cell_stresses(mesh, affine(mesh, G, {0, 0}), two_materials());
  ASSERT_EQ(s.stress.size(), 12u);
  ASSERT_EQ(s.von_mises.size(), 3u);
  const double e11 = 1e-3, e22 = -5e-4, g12 = 2e-3;

  // Triangle 0, sub-domain 1, plane strain E = 200, nu = 0.3.
  {
    const double E = 200, nu = 0.3, k = E / ((1 + nu) * (1 - 2 * nu));
    const double s11 = k * ((1 - nu) * e11 + nu * e22);
    const double s22 = k * (nu * e11 + (1 - nu) * e22);
    const double s12 = E / (2 * (1 + nu)) * g12;
    const double s33 = nu * (s11 + s22);
    EXPECT_NEAR(s.stress[0], s11, 1e-12);
    EXPECT_NEAR(s.stress[1], s22, 1e-12);
    EXPECT_NEAR(s.stress[2], s12, 1e-12);
    EXPECT_NEAR(s.stress[3], s33, 1e-12);
    const double vm = std::sqrt(
        0.5 * ((s11 - s22) * (s11 - s22) + (s22 - s33) * (s22 - s33) + (s33 - s11) * (s33 - s11)) +
        3 * s12 * s12);
    EXPECT_NEAR(s.von_mises[0], vm, 1e-12);
  }
  // Triangles 1 and 2, sub-domain 2, plane stress E = 100, nu = 0.25.
  for (int t : {1, 2}) {
    const double E = 100, nu = 0.25, k = E / (1 - nu * nu);
    const double s11 = k * (e11 + nu * e22);
    const double s22 = k * (nu * e11 + e22);
    const double s12 = E / (2 * (1 + nu)) * g12;
    EXPECT_NEAR(s.stress[4 * t + 0], s11, 1e-12);
    EXPECT_NEAR(s.stress[4 * t + 1], s22, 1e-12);
    EXPECT_NEAR(s.stress[4 * t + 2], s12, 1e-12);
    EXPECT_EQ(s.stress[4 * t + 3], 0.0);
    EXPECT_NEAR(s.von_mises[t], std::sqrt(s11 * s11 - s11 * s22 + s22 * s22 + 3 * s12 * s12),
                1e-12);
  }
}

TEST(Stress, MissingMaterialOrWrongSizeIsAnError) {
  const Mesh mesh = test::small_mesh();
  MaterialTable only_one = two_materials();
  only_one.entries.pop_back();
  const std::vector<double> u(2 * mesh.nodes.size(), 0.0);
  EXPECT_THROW(cell_stresses(mesh, u, only_one), Error);
  EXPECT_THROW(cell_stresses(mesh, std::vector<double>(3, 0.0), two_materials()), Error);
}

} // namespace
} // namespace sig

namespace sig {
namespace {

MaterialTable hyperelastic_materials() {
  MaterialTable table;
  for (int subdomain : {1, 2}) {
    SubdomainMaterial m;
    m.subdomain = subdomain;
    m.hyperelastic = std::make_shared<SaintVenantKirchhoff>(200.0, 0.3, PlaneMode::strain);
    m.hooke = m.hyperelastic->linearized();
    table.entries.push_back(m);
  }
  return table;
}

TEST(Stress, HyperelasticLawsGiveTheCauchyStressOfTheirFiniteRotation) {
  // A finite rigid rotation is stress-free for a hyperelastic law (and not for Hooke's).
  const Mesh mesh = test::small_mesh();
  const double angle = 0.8;
  Eigen::Matrix2d G;
  G << std::cos(angle) - 1, -std::sin(angle), std::sin(angle), std::cos(angle) - 1;
  const auto u = affine(mesh, G, {1, 2});
  const CellStress s = cell_stresses(mesh, u, hyperelastic_materials());
  for (double v : s.stress)
    EXPECT_NEAR(v, 0.0, 1e-10);
  EXPECT_NEAR(strain_energy(mesh, u, hyperelastic_materials()), 0.0, 1e-12);
}

TEST(Stress, HyperelasticStressTendsToHookesForSmallStrain) {
  const Mesh mesh = test::small_mesh();
  Eigen::Matrix2d G;
  G << 1e-7, 3e-8, -2e-8, -2e-7;
  const auto u = affine(mesh, G, {0, 0});
  const CellStress large = cell_stresses(mesh, u, hyperelastic_materials());
  MaterialTable linear = hyperelastic_materials();
  for (auto& m : linear.entries)
    m.hyperelastic.reset();
  const CellStress small = cell_stresses(mesh, u, linear);
  for (std::size_t i = 0; i < large.stress.size(); ++i) {
    if (i % 4 == 3) continue; // s33 is not computed for the hyperelastic laws
    EXPECT_NEAR(large.stress[i], small.stress[i], 1e-5 * 200 * 2e-7) << i;
  }
}

} // namespace
} // namespace sig
