// Hyperelastic laws (Ciarlet-Geymonat, Saint Venant-Kirchhoff) in plane strain and plane stress:
// stress and tangent against finite differences of energy and stress over random deformation
// gradients, the stress-free reference state, the small-strain limit against Hooke's law with
// Lame parameters derived by hand, objectivity, the out-of-plane stretch of plane stress against
// its closed forms, and the MATERIAL card / MILI round trip of the new laws.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "deformations.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/mili.hpp"
#include "material/saint_venant_kirchhoff.hpp"
#include "scratch_folder.hpp"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace sig {
namespace {

using Law = std::shared_ptr<const HyperelasticLaw>;

// Thesis ring values (Scene 7b) and a variant where the I2 term matters, plus SVK.
std::vector<Law> all_laws() {
  std::vector<Law> laws;
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    laws.push_back(std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35, plane));
    laws.push_back(std::make_shared<CiarletGeymonat>(1.2, 0.4, 2.0, plane));
    laws.push_back(std::make_shared<SaintVenantKirchhoff>(3.0, 0.3, plane));
  }
  return laws;
}

using test::describe;
using test::rotation;

// F = R(theta1) diag(s1, s2) R(theta2) with det F = s1 s2 uniform in [0.3, 3] and a stretch
// ratio s1 / s2 up to 2.6.
std::vector<Eigen::Matrix2d> random_gradients(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Matrix2d> result;
  for (int k = 0; k < count; ++k)
    result.push_back(test::random_gradient(rng, 0.3, 3.0, 0.5));
  return result;
}

// SVK has no plane-stress state under large in-plane stretching: C33 = 1 - 2 lambda tr(E) /
// (lambda + 2 mu) must be positive (saint_venant_kirchhoff.hpp).
bool in_domain(const HyperelasticLaw& law, const Eigen::Matrix2d& F) {
  if (law.plane() == PlaneMode::strain || law.name() != "svk") return true;
  const double trE = 0.5 * ((F.transpose() * F).trace() - 2.0);
  return 1.0 - 2.0 * law.lambda() * trE / (law.lambda() + 2.0 * law.mu()) > 0.05;
}

constexpr double step = 1e-5;

TEST(Hyperelastic, StressIsTheDerivativeOfTheEnergy) {
  for (const Law& law : all_laws()) {
    SCOPED_TRACE(describe(*law));
    int used = 0;
    for (const Eigen::Matrix2d& F : random_gradients(50, 11)) {
      if (!in_domain(*law, F)) continue;
      ++used;
      Eigen::Matrix2d numeric;
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) {
          Eigen::Matrix2d plus = F, minus = F;
          plus(i, J) += step;
          minus(i, J) -= step;
          numeric(i, J) = (law->energy(plus) - law->energy(minus)) / (2 * step);
        }
      const Eigen::Matrix2d P = law->stress(F);
      EXPECT_LT((P - numeric).norm(), 1e-6 * P.norm()) << "F =\n" << F;
    }
    EXPECT_GE(used, 30); // SVK plane stress loses the most stretched samples
  }
}

TEST(Hyperelastic, TangentIsTheDerivativeOfTheStress) {
  for (const Law& law : all_laws()) {
    SCOPED_TRACE(describe(*law));
    for (const Eigen::Matrix2d& F : random_gradients(50, 12)) {
      if (!in_domain(*law, F)) continue;
      Eigen::Matrix4d numeric;
      for (int k = 0; k < 2; ++k)
        for (int L = 0; L < 2; ++L) {
          Eigen::Matrix2d plus = F, minus = F;
          plus(k, L) += step;
          minus(k, L) -= step;
          const Eigen::Matrix2d dP = (law->stress(plus) - law->stress(minus)) / (2 * step);
          for (int i = 0; i < 2; ++i)
            for (int J = 0; J < 2; ++J)
              numeric(2 * i + J, 2 * k + L) = dP(i, J);
        }
      const Eigen::Matrix4d A = law->tangent(F);
      EXPECT_LT((A - numeric).norm(), 1e-6 * A.norm()) << "F =\n" << F;
      // A hyperelastic tangent is a second derivative: major symmetry.
      EXPECT_LT((A - A.transpose()).norm(), 1e-12 * A.norm());
    }
  }
}

// Plane strain's 2D closed form (at_plane_strain) against the 3D law at F3 = diag(F, 1): energy,
// P = F3 S and dP/dF = first_piola_tangent, their in-plane blocks, to rounding.
TEST(Hyperelastic, PlaneStrainIsTheInPlaneBlockOfThe3dLaw) {
  for (const Law& law : all_laws()) {
    if (law->plane() != PlaneMode::strain) continue;
    SCOPED_TRACE(describe(*law));
    for (const Eigen::Matrix2d& F : random_gradients(50, 13)) {
      Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
      F3.topLeftCorner<2, 2>() = F;
      const MaterialPoint3d point = law->at(F3.transpose() * F3);
      const Eigen::Matrix3d P3 = F3 * point.S;
      const Matrix9d A3 = first_piola_tangent(F3, point);
      const HyperelasticResponse r = law->response(F);
      EXPECT_NEAR(r.energy, point.energy, 1e-13 * (1 + std::abs(point.energy)));
      EXPECT_LT((r.stress - P3.topLeftCorner<2, 2>()).norm(), 1e-13 * (1 + P3.norm()));
      constexpr int in_plane[4] = {0, 1, 3, 4};
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          EXPECT_NEAR(r.tangent(a, b), A3(in_plane[a], in_plane[b]), 1e-13 * (1 + A3.norm()));
      const MaterialPoint2d p2 = law->in_plane(F.transpose() * F);
      EXPECT_LT((p2.S - point.S.topLeftCorner<2, 2>()).norm(), 1e-13 * (1 + point.S.norm()));
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          EXPECT_NEAR(p2.CC(a, b), point.CC(in_plane[a], in_plane[b]),
                      1e-13 * (1 + point.CC.norm()));
    }
  }
}

TEST(Hyperelastic, ReferenceStateIsStressFree) {
  for (const Law& law : all_laws()) {
    SCOPED_TRACE(describe(*law));
    const HyperelasticResponse r = law->response(Eigen::Matrix2d::Identity());
    EXPECT_EQ(r.energy, 0.0);
    EXPECT_EQ(r.stress.norm(), 0.0);
    EXPECT_DOUBLE_EQ(r.stretch33, 1.0);
    // A rigid rotation stores no energy either.
    const HyperelasticResponse q = law->response(rotation(0.7));
    EXPECT_LT(std::abs(q.energy), 1e-15 * law->mu());
    EXPECT_LT(q.stress.norm(), 1e-14 * law->mu());
  }
}

// The Lame parameters of the small-strain limit, derived by hand. Ciarlet-Geymonat: at
// C = I + 2 E, I1 = 3 + 2 tr E, I3 = 1 + 2 tr E + O(E^2), C^-1 = I - 2 E + O(E^2), so
// S/2 = c1 I + c2 (I1 I - C) + (a I3 - c1 - 2 c2 - a) C^-1
//     = 2 (a + c2) tr(E) I + 2 (c1 + c2) E + O(E^2):  lambda = 4 (a + c2), mu = 2 (c1 + c2).
// SVK: S = lambda tr(E) I + 2 mu E exactly.
Hooke small_strain_hooke(const HyperelasticLaw& law) {
  double lambda = 0.0, mu = 0.0;
  if (const auto* cg = dynamic_cast<const CiarletGeymonat*>(&law)) {
    lambda = 4.0 * (cg->a() + cg->c2());
    mu = 2.0 * (cg->c1() + cg->c2());
    Hooke h;
    h.nu = lambda / (2.0 * (lambda + mu));
    h.E = 2.0 * mu * (1.0 + h.nu);
    h.plane = law.plane();
    return h;
  }
  const auto& svk = dynamic_cast<const SaintVenantKirchhoff&>(law);
  return Hooke{svk.young(), svk.poisson(), law.plane()};
}

TEST(Hyperelastic, SmallStrainLimitIsHooke) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (const Law& law : all_laws()) {
    SCOPED_TRACE(describe(*law));
    const Hooke hooke = small_strain_hooke(*law);
    const Hooke linearized = law->linearized();
    EXPECT_NEAR(linearized.E, hooke.E, 1e-13 * hooke.E);
    EXPECT_NEAR(linearized.nu, hooke.nu, 1e-13);
    EXPECT_EQ(linearized.plane, hooke.plane);
    for (int sample = 0; sample < 10; ++sample) {
      Eigen::Matrix2d G;
      G << entry(rng), entry(rng), entry(rng), entry(rng);
      const double scale = 1e-7;
      const Eigen::Matrix2d P = law->stress(Eigen::Matrix2d::Identity() + scale * G);
      const Eigen::Vector3d eps(scale * G(0, 0), scale * G(1, 1), scale * (G(0, 1) + G(1, 0)));
      const Eigen::Vector3d sigma = hooke.stress(eps);
      Eigen::Matrix2d expected;
      expected << sigma(0), sigma(2), sigma(2), sigma(1);
      EXPECT_LT((P - expected).norm(), 1e-5 * expected.norm());
    }
    // The tangent at F = I is Hooke's D: A_iJkL = lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk).
    const Eigen::Matrix4d A = law->tangent(Eigen::Matrix2d::Identity());
    const Eigen::Matrix3d D = hooke.D();
    EXPECT_NEAR(A(0, 0), D(0, 0), 1e-12 * D.norm());
    EXPECT_NEAR(A(3, 3), D(1, 1), 1e-12 * D.norm());
    EXPECT_NEAR(A(0, 3), D(0, 1), 1e-12 * D.norm());
    for (int a : {1, 2})
      for (int b : {1, 2})
        EXPECT_NEAR(A(a, b), D(2, 2), 1e-12 * D.norm());
    EXPECT_NEAR(A(0, 1), 0.0, 1e-12 * D.norm());
  }
}

TEST(Hyperelastic, EnergyIsObjective) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  for (const Law& law : all_laws()) {
    SCOPED_TRACE(describe(*law));
    for (const Eigen::Matrix2d& F : random_gradients(20, 13)) {
      if (!in_domain(*law, F)) continue;
      const Eigen::Matrix2d Q = rotation(angle(rng));
      const HyperelasticResponse r = law->response(F), rq = law->response(Q * F);
      EXPECT_NEAR(rq.energy, r.energy, 1e-12 * std::abs(r.energy));
      // P(QF) = Q P(F): the stress turns with the body.
      EXPECT_LT((rq.stress - Q * r.stress).norm(), 1e-12 * r.stress.norm());
    }
  }
}

TEST(Hyperelastic, PlaneStressStretchMatchesClosedForms) {
  // Ciarlet-Geymonat: S33 = 2 (c1 + c2 tr C2 + a det C2 - d / C33) with C = diag(C2, C33), so
  // C33 = d / (c1 + c2 tr C2 + a det C2). SVK: S33 = 0 gives E33 = -lambda tr E2 / (lambda +
  // 2 mu).
  const CiarletGeymonat cg(1.2, 0.4, 2.0, PlaneMode::stress);
  const SaintVenantKirchhoff svk(3.0, 0.3, PlaneMode::stress);
  for (const Eigen::Matrix2d& F : random_gradients(30, 21)) {
    const Eigen::Matrix2d C2 = F.transpose() * F;
    const double d = cg.c1() + 2 * cg.c2() + cg.a();
    const double c33 = d / (cg.c1() + cg.c2() * C2.trace() + cg.a() * C2.determinant());
    EXPECT_NEAR(std::pow(cg.response(F).stretch33, 2), c33, 1e-13 * c33);
    if (!in_domain(svk, F)) {
      EXPECT_THROW(svk.response(F), Error);
      continue;
    }
    const double trE2 = 0.5 * (C2.trace() - 2.0);
    const double E33 = -svk.lambda() * trE2 / (svk.lambda() + 2 * svk.mu());
    EXPECT_NEAR(std::pow(svk.response(F).stretch33, 2), 1 + 2 * E33, 1e-13);
  }
  // Equibiaxial stretch 1.5: tr E2 = 1.25 > (lambda + 2 mu) / (2 lambda) = 7/6 at nu = 0.3.
  EXPECT_THROW(svk.response(1.5 * Eigen::Matrix2d::Identity()), Error);
}

TEST(Hyperelastic, InvertedGradientIsAnError) {
  Eigen::Matrix2d F;
  F << 1, 0, 0, -0.5;
  for (const Law& law : all_laws())
    EXPECT_THROW(law->response(F), Error) << describe(*law);
  EXPECT_THROW(CiarletGeymonat(0.0, 0.1, 0.1), Error);
  EXPECT_THROW(SaintVenantKirchhoff(1.0, 0.5), Error);
}

// ---- MATERIAL card and MILI ----

const Card& first_card(const Datafile& d) {
  return d.cards().front();
}

TEST(HyperelasticCard, ReadsBothLaws) {
  const Datafile d = Datafile::parse(
      "MATERIAL law=ciarlet-geymonat c1=0.5 c2=0.005 a=0.35 plane=stress rho=1000\n", "m.dat");
  const SubdomainMaterial m = material_from_card(first_card(d));
  ASSERT_TRUE(m.hyperelastic);
  const auto* cg = dynamic_cast<const CiarletGeymonat*>(m.hyperelastic.get());
  ASSERT_NE(cg, nullptr);
  EXPECT_EQ(cg->c1(), 0.5);
  EXPECT_EQ(cg->c2(), 0.005);
  EXPECT_EQ(cg->a(), 0.35);
  EXPECT_EQ(cg->plane(), PlaneMode::stress);
  // Hooke's law of the entry is the small-strain limit: lambda = 1.42, mu = 1.01.
  EXPECT_NEAR(m.hooke.nu, 1.42 / (2 * 2.43), 1e-14);
  EXPECT_NEAR(m.hooke.E, 2 * 1.01 * (1 + 1.42 / (2 * 2.43)), 1e-13);
  EXPECT_EQ(m.hooke.plane, PlaneMode::stress);
  EXPECT_EQ(m.density, 1000.0);

  const Datafile s = Datafile::parse("MATERIAL law=svk E=2 nu=0.25\n", "m.dat");
  const SubdomainMaterial n = material_from_card(first_card(s));
  ASSERT_TRUE(n.hyperelastic);
  EXPECT_EQ(n.hyperelastic->name(), "svk");
  EXPECT_EQ(n.hyperelastic->plane(), PlaneMode::strain);
  EXPECT_NEAR(n.hyperelastic->mu(), 0.8, 1e-15);
  EXPECT_EQ(n.hooke.E, 2.0);

  const Datafile h = Datafile::parse("MATERIAL E=2 nu=0.25\n", "m.dat");
  EXPECT_FALSE(material_from_card(first_card(h)).hyperelastic);
}

TEST(HyperelasticCard, BadFieldsAreInputErrors) {
  struct Case {
    const char* text;
    const char* field;
  };
  for (const Case c : {Case{"MATERIAL law=ciarlet-geymonat c1=0 c2=0 a=1", "c1"},
                       Case{"MATERIAL law=ciarlet-geymonat c1=1 c2=-1 a=1", "c2"},
                       Case{"MATERIAL law=ciarlet-geymonat c1=1 c2=0 a=-1", "a"},
                       Case{"MATERIAL law=ciarlet-geymonat c1=1 a=1", "c2"},
                       Case{"MATERIAL law=ciarlet-geymonat E=1 c1=1 c2=0 a=1", "e"},
                       Case{"MATERIAL law=svk E=1 nu=0.3 c1=2", "c1"},
                       Case{"MATERIAL law=svk E=1 nu=0.5", "nu"}}) {
    const Datafile d = Datafile::parse(std::string(c.text) + "\n", "m.dat");
    try {
      material_from_card(first_card(d));
      ADD_FAILURE() << c.text << ": no InputError";
    } catch (const InputError& e) {
      std::string field = e.field();
      for (char& ch : field)
        ch = static_cast<char>(std::tolower(ch));
      EXPECT_EQ(field, c.field) << c.text << ": " << e.what();
    }
  }
}

TEST(HyperelasticCard, MiliRoundTripKeepsTheLaws) {
  const Datafile d =
      Datafile::parse("MATERIAL law=ciarlet-geymonat c1=0.5 c2=0.005 a=0.35\n", "m.dat");
  const Datafile s = Datafile::parse("MATERIAL law=svk E=2 nu=0.25 plane=stress\n", "m.dat");
  MaterialTable table;
  table.entries = {material_from_card(first_card(d)), material_from_card(first_card(s)),
                   SubdomainMaterial{}};
  for (int i = 0; i < 3; ++i)
    table.entries[i].subdomain = i + 1;
  const testing::ScratchFolder dir;
  const auto path = dir / "case.mili";
  write_mili(path, table, "hyperelastic round trip");
  const MaterialTable back = read_mili(path);
  ASSERT_EQ(back.entries.size(), 3u);
  const Eigen::Matrix2d F{{1.3, 0.2}, {-0.1, 0.8}};
  for (int i = 0; i < 2; ++i) {
    const SubdomainMaterial& x = table.entries[i];
    const SubdomainMaterial& y = back.entries[i];
    ASSERT_TRUE(y.hyperelastic);
    EXPECT_EQ(y.hyperelastic->name(), x.hyperelastic->name());
    EXPECT_EQ(y.hyperelastic->plane(), x.hyperelastic->plane());
    EXPECT_EQ(y.hyperelastic->energy(F), x.hyperelastic->energy(F));
    EXPECT_NEAR(y.hooke.E, x.hooke.E, 1e-15 * x.hooke.E);
  }
  EXPECT_FALSE(back.entries[2].hyperelastic);
}

} // namespace
} // namespace sig
