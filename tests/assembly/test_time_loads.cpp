// MOVINGLOAD (assembly/time_loads.hpp): its quadrature exact for a constant load and within
// 1e-7 of the closed form of a Gaussian on a coarse edge (where one 3-point rule is not), the
// load at t equal to the static load centred at x0 + c t, its errors with file, line and field,
// and its round trip through the TAE.
#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "scratch_folder.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace sig {
namespace {

LinearSystem assemble(const Mesh& mesh, const std::string& deck) {
  const Datafile datafile = Datafile::parse(deck, "rail.dat");
  return assemble_system(mesh, material_table_from_cards(datafile, mesh), datafile);
}

const std::string kMaterials = "MATERIAL region=1 E=1 nu=0.3\n"
                               "MATERIAL region=2 E=1 nu=0.3 thickness=0.5\n";

// A Gaussian too wide to vary over the mesh is the constant traction: the rule integrates the
// P1 basis exactly, on edges of both sub-domains (two thicknesses) and of any direction.
TEST(MovingLoad, ExactForAConstantLoad) {
  const Mesh mesh = test::square_mesh(5, 3, 2.0, 0.2, 2);
  for (const char* ref : {"3", "2", "1,2,3,4"}) {
    const LinearSystem moving =
        assemble(mesh, kMaterials + "MOVINGLOAD ref=" + ref + " F=2.5 psi=1e-16 c=3 x0=0.7\n");
    const LinearSystem constant =
        assemble(mesh, kMaterials + "TRACTION ref=" + ref + " f=0,-2.5\n");
    EXPECT_LT((moving.f - constant.f).norm(), 1e-14 * constant.f.norm()) << "ref " << ref;
    EXPECT_LT((moving.load_at(0.4) - constant.f).norm(), 1e-14 * constant.f.norm());
  }
}

// The nodal forces of exp(-psi (x - m)^2) on the edge [0, 1] against the P1 basis, in closed
// form (erf), and by one 3-point Gauss rule over the whole edge.
Eigen::Vector2d exact_nodal_forces(double psi, double m) {
  const double s = std::sqrt(psi);
  const double i0 =
      std::sqrt(std::numbers::pi / psi) / 2 * (std::erf(s * (1 - m)) - std::erf(s * (0 - m)));
  const double i1 = -(std::exp(-psi * (1 - m) * (1 - m)) - std::exp(-psi * m * m)) / (2 * psi);
  const double ix = i1 + m * i0; // int x g
  return {i0 - ix, ix};
}

Eigen::Vector2d one_gauss_rule(double psi, double m) {
  const double x[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
  const double w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  for (int q = 0; q < 3; ++q)
    f += w[q] * std::exp(-psi * (x[q] - m) * (x[q] - m)) * Eigen::Vector2d(1 - x[q], x[q]);
  return f;
}

// The thesis's h = 1/2: one top edge of 1 m under a Gaussian of standard deviation 0.1 m.
TEST(MovingLoad, CompositeRuleResolvesTheGaussianOnACoarseEdge) {
  const Mesh mesh = test::square_mesh(1, 1); // top edge (1, 1) - (0, 1), reference 3
  const int a = 2, b = 3;                    // nodes (0, 1) and (1, 1)
  ASSERT_EQ(mesh.nodes[a], Eigen::Vector2d(0, 1));
  ASSERT_EQ(mesh.nodes[b], Eigen::Vector2d(1, 1));
  double worst_single = 0;
  for (double m : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0}) {
    const LinearSystem s = assemble(
        mesh,
        "MATERIAL E=1 nu=0.3\nMOVINGLOAD ref=3 F=1 psi=50 c=0 x0=" + std::to_string(m) + "\n");
    const Eigen::Vector2d exact = exact_nodal_forces(50, m);
    const Eigen::Vector2d ours(-s.f[2 * a + 1], -s.f[2 * b + 1]);
    EXPECT_LT((ours - exact).norm(), 1e-7 * exact.sum()) << "centre " << m;
    worst_single = std::max(worst_single, (one_gauss_rule(50, m) - exact).norm() / exact.sum());
  }
  // Why the composite rule: one 3-point rule misses by tens of per cent there.
  EXPECT_GT(worst_single, 0.3);
}

TEST(MovingLoad, LoadAtTEqualsTheStaticLoadCentredAtX0PlusCT) {
  const Mesh mesh = test::square_mesh(16, 2, 2.0, 0.1);
  const std::string base = "MATERIAL E=100 nu=0.3 rho=1e-6\nTRACTION ref=2 f=1,0\n"
                           "DIRICHLET ref=4 ux=0 uy=0.01\n";
  const LinearSystem moving = assemble(mesh, base + "MOVINGLOAD ref=3 F=10 psi=50 c=2 x0=0.1\n");
  for (double t : {0.0, 0.2, 0.45, 1.0}) {
    const LinearSystem fixed = assemble(
        mesh, base + "MOVINGLOAD ref=3 F=10 psi=50 c=0 x0=" + std::to_string(0.1 + 2 * t) + "\n");
    EXPECT_LT((moving.load_at(t) - fixed.f).norm(), 1e-12 * fixed.f.norm()) << "t = " << t;
    // The reduced loads too (Dirichlet elimination, what a march applies).
    EXPECT_LT((reduce(moving).load_at(t) - reduce(fixed).f).norm(), 1e-12 * fixed.f.norm());
  }
  // Its resultant, F sqrt(pi / psi) with the Gaussian inside the top edge, downwards.
  const Eigen::VectorXd f = moving.load_at(0.45) - assemble(mesh, base).f;
  EXPECT_NEAR(f(Eigen::seqN(1, f.size() / 2, 2)).sum(), -10 * std::sqrt(std::numbers::pi / 50),
              1e-9);
  EXPECT_EQ(f(Eigen::seqN(0, f.size() / 2, 2)).norm(), 0.0);
}

TEST(MovingLoad, BadCardsNameFileLineAndField) {
  const Mesh mesh = test::square_mesh(2, 2);
  const auto expect_error = [&](const std::string& card, const std::string& field,
                                const std::string& detail) {
    try {
      assemble(mesh, "MATERIAL E=1 nu=0.3\n# the moving mass\n" + card + "\n");
      ADD_FAILURE() << "no InputError for " << card;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "rail.dat");
      EXPECT_EQ(e.line(), 3);
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(detail), std::string::npos) << e.what();
    }
  };
  expect_error("MOVINGLOAD ref=3 F=10 psi=0 c=2", "psi", "must be > 0");
  expect_error("MOVINGLOAD ref=3 F=10 psi=-50 c=2", "psi", "got -50");
  expect_error("MOVINGLOAD ref=3 F=10 c=2", "psi", "missing");
  expect_error("MOVINGLOAD ref=3 psi=50 c=2", "F", "missing");
  expect_error("MOVINGLOAD ref=3 F=10 psi=50", "c", "missing");
  expect_error("MOVINGLOAD ref=9 F=10 psi=50 c=2", "ref", "reference 9");
  expect_error("MOVINGLOAD ref=3 F=10 psi=nan c=2", "psi", "finite");
}

TEST(MovingLoad, TaeRoundTrip) {
  const Mesh mesh = test::square_mesh(6, 2, 1.0, 0.2, 2);
  const LinearSystem s = assemble(mesh, kMaterials + "MOVINGLOAD ref=3 F=10 psi=50 c=2\n"
                                                     "MOVINGLOAD ref=1 F=-1 psi=200 c=-1 x0=1\n");
  ASSERT_EQ(s.time_loads.moving.size(), 2u);
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "moving");
  const LinearSystem back = read_tae(path);
  EXPECT_EQ(back.f, s.f);
  for (double t : {0.0, 0.3, 0.7})
    EXPECT_EQ(back.load_at(t), s.load_at(t));
  // Without a moving load the TAE has no moving arrays and the load is constant.
  const LinearSystem plain = assemble(mesh, kMaterials + "TRACTION ref=3 f=0,-1\n");
  EXPECT_TRUE(plain.time_loads.empty());
  EXPECT_EQ(plain.load_at(0.5), plain.f);
}

} // namespace
} // namespace sig
