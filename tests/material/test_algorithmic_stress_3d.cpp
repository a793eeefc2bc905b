// The stress of a midpoint time step in 3D (material/algorithmic_stress.hpp, the thesis's (3.41)
// on the 3 x 3 C): Gonzalez's energy identity (3.42) for random pairs of 3D deformation
// gradients, both stresses' tangents against central differences, Pi F_m^T symmetric (the
// angular momentum), the plain midpoint stress missing the identity, and plane strain as the 3D
// formula at F33 = 1 (the 2D and 3D stresses are one template).
#include "material/algorithmic_stress.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/saint_venant_kirchhoff.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace sig {
namespace {

using Law = std::shared_ptr<const HyperelasticLaw>;

std::vector<Law> laws() {
  return {std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35), // the ring's
          std::make_shared<CiarletGeymonat>(1.2, 0.4, 2.0),
          std::make_shared<SaintVenantKirchhoff>(3.0, 0.3)};
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

/// A rotation times I + 0.3 N (N standard normal), drawn again until det F is in [0.5, 2].
Eigen::Matrix3d random_gradient(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  while (true) {
    const Eigen::Matrix3d F =
        random_rotation(rng) * (Eigen::Matrix3d::Identity() +
                                0.3 * Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); }));
    if (F.determinant() > 0.5 && F.determinant() < 2.0) return F;
  }
}

/// A large step from F0: a random rotation of F0 plus a random change of size 0.3, drawn again
/// until F1 and the midpoint are well inside the domain and the energy changes by more than
/// rounding.
Eigen::Matrix3d large_step(const HyperelasticLaw& law, const Eigen::Matrix3d& F0,
                           std::mt19937& rng) {
  std::normal_distribution<double> normal;
  while (true) {
    const Eigen::Matrix3d F1 =
        random_rotation(rng) * F0 + 0.3 * Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); });
    if (F1.determinant() < 0.3 || (0.5 * (F0 + F1)).determinant() < 0.3) continue;
    const double W0 = step_energy(law, F0), W1 = step_energy(law, F1);
    if (std::abs(W1 - W0) > 1e-2 * (std::abs(W1) + std::abs(W0))) return F1;
  }
}

double contract(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  return (A.array() * B.array()).sum();
}

// (3.42) in 3D: Pi : (F_n - F_{n-1}) = W(C_n) - W(C_{n-1}) to rounding, for large steps and for
// small ones down to below the rigid-step threshold.
TEST(GonzalezStress3d, EnergyIdentityHoldsForRandomSteps) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (const Law& law : laws()) {
    SCOPED_TRACE(law->name());
    double worst = 0, worst_small = 0;
    for (int sample = 0; sample < 100; ++sample) {
      const Eigen::Matrix3d F0 = random_gradient(rng);
      const double W0 = step_energy(*law, F0);
      for (double h : {0.0, 1e-2, 1e-4, 1e-7, 1e-9}) {
        const Eigen::Matrix3d F1 =
            h > 0 ? Eigen::Matrix3d(F0 +
                                    h * Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); }))
                  : large_step(*law, F0, rng);
        const double W1 = step_energy(*law, F1);
        const StepResponse s = step_response(*law, AlgorithmicStress::gonzalez, F0, W0, F1);
        EXPECT_EQ(s.energy, W1);
        const double error = std::abs(contract(s.stress, F1 - F0) - (W1 - W0));
        if (h == 0.0)
          worst = std::max(worst, error / std::abs(W1 - W0));
        else
          worst_small = std::max(worst_small, error / (std::abs(W0) + std::abs(W1)));
      }
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worst_small, 1e-13);
  }
}

// The plain midpoint stress misses the identity by O(step^3): visible for a large step.
TEST(MidpointStress3d, MissesTheEnergyIdentity) {
  std::mt19937 rng(9);
  const CiarletGeymonat law(0.5, 0.005, 0.35);
  double largest = 0;
  for (int sample = 0; sample < 50; ++sample) {
    const Eigen::Matrix3d F0 = random_gradient(rng), F1 = large_step(law, F0, rng);
    const double W0 = step_energy(law, F0), W1 = step_energy(law, F1);
    const StepResponse s = step_response(law, AlgorithmicStress::midpoint, F0, W0, F1);
    largest =
        std::max(largest, std::abs(contract(s.stress, F1 - F0) - (W1 - W0)) / std::abs(W1 - W0));
  }
  EXPECT_GT(largest, 1e-2);
}

// dPi / dF_n against central differences of Pi (Voigt index 3 i + J), both stresses; and
// Pi F_m^T symmetric, so that the step's internal forces have no moment.
TEST(StepStress3d, TangentIsTheDerivativeAndTheMomentVanishes) {
  std::mt19937 rng(17);
  std::normal_distribution<double> normal;
  for (const Law& law : laws()) {
    SCOPED_TRACE(law->name());
    for (AlgorithmicStress kind : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint}) {
      SCOPED_TRACE(to_string(kind));
      double worst = 0, worst_moment = 0;
      for (int sample = 0; sample < 20; ++sample) {
        const Eigen::Matrix3d F0 = random_gradient(rng);
        const double W0 = step_energy(*law, F0);
        for (double h : {0.0, 1e-1, 1e-3}) {
          const Eigen::Matrix3d F1 =
              h > 0 ? Eigen::Matrix3d(F0 +
                                      h * Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); }))
                    : large_step(*law, F0, rng);
          const StepResponse s = step_response(*law, kind, F0, W0, F1);
          const double e = 1e-6;
          Matrix9d fd;
          for (int b = 0; b < 9; ++b) {
            Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();
            dF(b / 3, b % 3) = e;
            const Eigen::Matrix3d d = (step_response(*law, kind, F0, W0, F1 + dF, false).stress -
                                       step_response(*law, kind, F0, W0, F1 - dF, false).stress) /
                                      (2 * e);
            for (int a = 0; a < 9; ++a)
              fd(a, b) = d(a / 3, a % 3);
          }
          worst = std::max(worst, (s.tangent - fd).norm() / fd.norm());
          const Eigen::Matrix3d moment = s.stress * (0.5 * (F0 + F1)).transpose();
          worst_moment =
              std::max(worst_moment, (moment - moment.transpose()).norm() / moment.norm());
        }
      }
      EXPECT_LT(worst, 1e-6);
      EXPECT_LT(worst_moment, 1e-13);
    }
  }
}

// Plane strain is the 3D formula at F33 = 1 on both ends of the step (dC33 = 0): the 2D step's
// stress, tangent and energy are the in-plane blocks of the 3D step's.
TEST(StepStress3d, PlaneStrainIsTheThreeDimensionalStepAtUnitF33) {
  std::mt19937 rng(31);
  std::normal_distribution<double> normal;
  constexpr int in_plane[4] = {0, 1, 3, 4};
  const CiarletGeymonat law(0.5, 0.005, 0.35, PlaneMode::strain);
  for (int sample = 0; sample < 20; ++sample) {
    Eigen::Matrix2d F0, F1;
    do {
      F0 = Eigen::Matrix2d::Identity() +
           0.3 * Eigen::Matrix2d::NullaryExpr([&] { return normal(rng); });
      F1 = F0 + 0.3 * Eigen::Matrix2d::NullaryExpr([&] { return normal(rng); });
    } while (F0.determinant() < 0.3 || F1.determinant() < 0.3 ||
             (0.5 * (F0 + F1)).determinant() < 0.3);
    Eigen::Matrix3d G0 = Eigen::Matrix3d::Identity(), G1 = Eigen::Matrix3d::Identity();
    G0.topLeftCorner<2, 2>() = F0;
    G1.topLeftCorner<2, 2>() = F1;
    for (AlgorithmicStress kind : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint}) {
      const StepResponse two = step_response(law, kind, F0, step_energy(law, F0), F1);
      const StepResponse three = step_response(law, kind, G0, step_energy(law, G0), G1);
      EXPECT_NEAR(two.energy, three.energy, 1e-14 * std::abs(three.energy));
      EXPECT_LT((two.stress - three.stress.topLeftCorner<2, 2>()).norm(),
                1e-12 * three.stress.norm());
      Eigen::Matrix4d block;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          block(a, b) = three.tangent(in_plane[a], in_plane[b]);
      EXPECT_LT((two.tangent - block).norm(), 1e-12 * block.norm());
    }
  }
}

} // namespace
} // namespace sig
