// Hooke's law: the matrix D against closed forms, its energy against the stress by quadrature
// and finite differences, and the checks of the MATERIAL card.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/hooke.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

namespace sig {
namespace {

Hooke law(double E, double nu, PlaneMode plane) {
  Hooke h;
  h.E = E;
  h.nu = nu;
  h.plane = plane;
  return h;
}

TEST(Hooke, DIsSymmetricPositiveDefinite) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress})
    for (double nu : {-0.9, -0.3, 0.0, 0.25, 0.3, 0.45, 0.499}) {
      const Eigen::Matrix3d D = law(7.5, nu, plane).D();
      EXPECT_LT((D - D.transpose()).norm(), 1e-14 * D.norm());
      const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(D).eigenvalues();
      EXPECT_GT(eig.minCoeff(), 0.0) << "nu = " << nu;
    }
}

TEST(Hooke, PlaneStrainKnownValues) {
  // E = 1, nu = 1/4: E / ((1 + nu)(1 - 2 nu)) = 1.6, so D11 = 1.6 * 3/4, D12 = 1.6 / 4 and
  // D33 = mu = 1 / (2 * 5/4).
  const Eigen::Matrix3d D = law(1.0, 0.25, PlaneMode::strain).D();
  Eigen::Matrix3d expected;
  expected << 1.2, 0.4, 0, 0.4, 1.2, 0, 0, 0, 0.4;
  EXPECT_LT((D - expected).norm(), 1e-15);
}

TEST(Hooke, PlaneStressKnownValues) {
  // E / (1 - nu^2) = 16/15: D11 = 16/15, D12 = 4/15, D33 = (16/15)(3/8) = 0.4.
  const Eigen::Matrix3d D = law(1.0, 0.25, PlaneMode::stress).D();
  Eigen::Matrix3d expected;
  expected << 16.0 / 15, 4.0 / 15, 0, 4.0 / 15, 16.0 / 15, 0, 0, 0, 0.4;
  EXPECT_LT((D - expected).norm(), 1e-15);
}

TEST(Hooke, UniaxialStressRecoversYoungsModulus) {
  const double E = 210.0, nu = 0.3;
  // Plane stress: eps = (1, -nu, 0) is a uniaxial stress state sigma = (E, 0, 0).
  const Eigen::Vector3d s1 = law(E, nu, PlaneMode::stress).stress({1.0, -nu, 0.0});
  EXPECT_NEAR(s1(0), E, 1e-12 * E);
  EXPECT_NEAR(s1(1), 0.0, 1e-12 * E);
  // Plane strain: sigma22 = 0 needs eps22 = -nu/(1 - nu) eps11, and then s11 = E/(1 - nu^2).
  const Hooke strain = law(E, nu, PlaneMode::strain);
  const Eigen::Vector3d eps(1.0, -nu / (1 - nu), 0.0);
  const Eigen::Vector3d s2 = strain.stress(eps);
  EXPECT_NEAR(s2(0), E / (1 - nu * nu), 1e-12 * E);
  EXPECT_NEAR(s2(1), 0.0, 1e-12 * E);
  EXPECT_NEAR(strain.stress33(eps), nu * s2(0), 1e-12 * E);
}

TEST(Hooke, EnergyIsTheIntegralOfTheStress) {
  const Eigen::Vector3d eps(0.3, -0.7, 0.45);
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const Hooke h = law(3.0, 0.35, plane);
    // W(eps) = int_0^1 sigma(s eps) . eps ds; Simpson is exact for the linear integrand.
    const double integral =
        (h.stress(0 * eps).dot(eps) + 4 * h.stress(0.5 * eps).dot(eps) + h.stress(eps).dot(eps)) /
        6.0;
    EXPECT_NEAR(h.energy_density(eps), integral, 1e-13);
    // dW/d eps = sigma, by central differences.
    const double step = 1e-6;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d plus = eps, minus = eps;
      plus(k) += step;
      minus(k) -= step;
      const double derivative = (h.energy_density(plus) - h.energy_density(minus)) / (2 * step);
      EXPECT_NEAR(derivative, h.stress(eps)(k), 1e-8) << "component " << k;
    }
  }
}

// von Mises from the full 3D tensor: sqrt(3/2 s:s) with s the deviator.
double von_mises_3d(const Eigen::Matrix3d& sigma) {
  const Eigen::Matrix3d s = sigma - sigma.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * (s.array() * s.array()).sum());
}

TEST(Hooke, VonMisesMatchesTheThreeDimensionalTensor) {
  const Eigen::Vector3d eps(0.2, -0.05, 0.13);
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const Hooke h = law(5.0, 0.3, plane);
    const Eigen::Vector3d s = h.stress(eps);
    const double s33 = plane == PlaneMode::strain ? 0.3 * (s(0) + s(1)) : 0.0;
    Eigen::Matrix3d sigma;
    sigma << s(0), s(2), 0, s(2), s(1), 0, 0, 0, s33;
    EXPECT_NEAR(h.von_mises(eps), von_mises_3d(sigma), 1e-13);
  }
  // Pure shear gamma: s12 = mu gamma and sigma_vm = sqrt(3) mu gamma in both modes.
  const Hooke h = law(2.6, 0.3, PlaneMode::strain);
  EXPECT_NEAR(h.von_mises({0, 0, 0.1}), std::sqrt(3.0) * 1.0 * 0.1, 1e-14);
}

} // namespace
} // namespace sig
