// The stress of a midpoint time step (material/algorithmic_stress.hpp), in 2D (on the plane
// mode's in-plane law) and in 3D (the thesis's (3.41) on the 3 x 3 C), each check one template on
// the dimension d: Gonzalez's energy identity (3.42) for random pairs of deformation gradients,
// far apart and close together; both stresses' tangents against central differences; the
// rigid-step limit; the symmetry of Pi F_m^T that conserves the angular momentum; the plain
// midpoint stress missing the identity; plane strain as the 3D step at F33 = 1; and the 2D
// material point against the 2D response it condenses.
#include "core/error.hpp"
#include "deformations.hpp"
#include "material/algorithmic_stress.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/saint_venant_kirchhoff.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace sig {
namespace {

using Law = std::shared_ptr<const HyperelasticLaw>;

/// The laws of the checks in R^d: in 2D each plane mode (plane stress for Ciarlet-Geymonat; SVK
/// loses its plane-stress state in compression), in 3D the laws themselves.
template <int d> std::vector<Law> laws() {
  std::vector<Law> out;
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    if (d == 3 && plane == PlaneMode::stress) continue;
    out.push_back(std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35, plane)); // the ring's
    out.push_back(std::make_shared<CiarletGeymonat>(1.2, 0.4, 2.0, plane));
  }
  out.push_back(std::make_shared<SaintVenantKirchhoff>(3.0, 0.3, PlaneMode::strain));
  return out;
}

template <int d> std::string describe(const HyperelasticLaw& law) {
  return d == 2 ? test::describe(law) : law.name() + " 3D";
}

template <int d> Tensor<d> normal_tensor(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Tensor<d>::NullaryExpr([&] { return normal(rng); });
}

/// A rotation: in 2D by an angle in [-1, 1] rad, in 3D a uniform one.
template <int d> Tensor<d> random_rotation(std::mt19937& rng) {
  if constexpr (d == 2) {
    std::uniform_real_distribution<double> angle(-1.0, 1.0);
    return test::rotation(angle(rng));
  } else {
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
        .normalized()
        .toRotationMatrix();
  }
}

/// det F in [0.5, 2], inside the plane-stress domain of every 2D law above: in 2D a stretch
/// ratio up to 1.8 between two rotations, in 3D a rotation of I + 0.3 N (N standard normal).
template <int d> Tensor<d> random_gradient(std::mt19937& rng) {
  if constexpr (d == 2) {
    return test::random_gradient(rng, 0.5, 2.0, 0.3);
  } else {
    while (true) {
      const Tensor<3> F =
          random_rotation<3>(rng) * (Tensor<3>::Identity() + 0.3 * normal_tensor<3>(rng));
      if (F.determinant() > 0.5 && F.determinant() < 2.0) return F;
    }
  }
}

/// W(F) of the law's response (in 2D: F33 from F in plane stress, where the step's energy finds
/// it from C: the two agree to rounding of the moduli).
template <int d> double energy(const HyperelasticLaw& law, const Tensor<d>& F) {
  return piola_response(law, F, false).energy;
}

/// The end of a large step from F0: a rotation and a random change of size 0.5, drawn again
/// until F1, the midpoint and the energy change are well defined (det > 0.2, and a change of
/// energy that is not itself a rounding-level difference).
template <int d>
Tensor<d> large_step(const HyperelasticLaw& law, const Tensor<d>& F0, std::mt19937& rng) {
  while (true) {
    const Tensor<d> F1 = random_rotation<d>(rng) * F0 + 0.5 * normal_tensor<d>(rng);
    if (F1.determinant() < 0.2 || (0.5 * (F0 + F1)).determinant() < 0.2) continue;
    const double W0 = energy<d>(law, F0), W1 = energy<d>(law, F1);
    if (std::abs(W1 - W0) > 1e-2 * (std::abs(W1) + std::abs(W0))) return F1;
  }
}

template <int d> double contract(const Tensor<d>& A, const Tensor<d>& B) {
  return (A.array() * B.array()).sum();
}

/// (3.42): Pi : (F_n - F_{n-1}) = W(C_n) - W(C_{n-1}), exactly up to rounding, for steps of
/// every size down to the rigid-step threshold and below it.
template <int d> void expect_energy_identity() {
  std::mt19937 rng(5);
  for (const Law& law : laws<d>()) {
    SCOPED_TRACE(describe<d>(*law));
    double worst = 0, worst_small = 0;
    for (int sample = 0; sample < 100; ++sample) {
      const Tensor<d> F0 = random_gradient<d>(rng);
      // Far apart (an independent F), then steps of size 1e-2 ... 1e-9 around F0.
      for (double h : {0.0, 1e-2, 1e-4, 1e-6, 1e-7, 1e-9}) {
        const Tensor<d> F1 =
            h > 0 ? Tensor<d>(F0 + h * normal_tensor<d>(rng)) : large_step<d>(*law, F0, rng);
        // The identity is on the step's energies, W(C) (in plane stress C33 from C); the
        // response's W(F) is the same to rounding of the moduli.
        const double W0 = step_energy(*law, F0), W1 = step_energy(*law, F1);
        const StepResponse s = step_response(*law, AlgorithmicStress::gonzalez, F0, W0, F1);
        const double error = std::abs(contract<d>(s.stress, F1 - F0) - (W1 - W0));
        EXPECT_EQ(s.energy, W1);
        EXPECT_NEAR(s.energy, energy<d>(*law, F1), 1e-14 * (std::abs(W1) + law->mu()));
        if (h == 0.0) {
          worst = std::max(worst, error / std::abs(W1 - W0));
        } else {
          // Relative to the energy and the moduli (the rounding of W, in plane stress of its
          // C33 too): W1 - W0 is itself a rounding-level difference for tiny h.
          worst_small = std::max(worst_small, error / (std::abs(W0) + std::abs(W1) + law->mu()));
        }
      }
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worst_small, 1e-13);
  }
}

TEST(GonzalezStress, EnergyIdentityHoldsForRandomSteps) {
  expect_energy_identity<2>();
  expect_energy_identity<3>();
}

// The plain midpoint stress is consistent but misses the identity by O(step^3): visible for a
// large step, which is what Gonzalez's correction removes.
template <int d> void expect_midpoint_misses_the_identity() {
  std::mt19937 rng(9);
  const CiarletGeymonat law(0.5, 0.005, 0.35);
  double largest = 0;
  for (int sample = 0; sample < 50; ++sample) {
    const Tensor<d> F0 = random_gradient<d>(rng), F1 = large_step<d>(law, F0, rng);
    const double W0 = energy<d>(law, F0), W1 = energy<d>(law, F1);
    const StepResponse s = step_response(law, AlgorithmicStress::midpoint, F0, W0, F1);
    largest =
        std::max(largest, std::abs(contract<d>(s.stress, F1 - F0) - (W1 - W0)) / std::abs(W1 - W0));
  }
  EXPECT_GT(largest, 1e-2);
}

TEST(MidpointStress, MissesTheEnergyIdentity) {
  expect_midpoint_misses_the_identity<2>();
  expect_midpoint_misses_the_identity<3>();
}

// dPi / dF_n against central differences of Pi (Voigt index d i + J), for both stresses, at
// large and small steps and at a step just above the rigid threshold.
template <int d> void expect_tangent_is_the_derivative() {
  std::mt19937 rng(17);
  for (const Law& law : laws<d>()) {
    SCOPED_TRACE(describe<d>(*law));
    for (AlgorithmicStress kind : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint}) {
      SCOPED_TRACE(to_string(kind));
      double worst = 0;
      for (int sample = 0; sample < 30; ++sample) {
        const Tensor<d> F0 = random_gradient<d>(rng);
        const double W0 = energy<d>(*law, F0);
        for (double h : {0.0, 1e-1, 1e-3}) {
          const Tensor<d> F1 =
              h > 0 ? Tensor<d>(F0 + h * normal_tensor<d>(rng)) : large_step<d>(*law, F0, rng);
          const StepResponse s = step_response(*law, kind, F0, W0, F1);
          const double e = 1e-6;
          TensorMap<d> fd;
          for (int b = 0; b < d * d; ++b) {
            Tensor<d> dF = Tensor<d>::Zero();
            dF(b / d, b % d) = e;
            const Tensor<d> plus = step_response(*law, kind, F0, W0, F1 + dF, false).stress;
            const Tensor<d> minus = step_response(*law, kind, F0, W0, F1 - dF, false).stress;
            for (int a = 0; a < d * d; ++a)
              fd(a, b) = (plus(a / d, a % d) - minus(a / d, a % d)) / (2 * e);
          }
          worst = std::max(worst, (s.tangent - fd).norm() / fd.norm());
        }
      }
      EXPECT_LT(worst, 1e-6);
    }
  }
}

TEST(StepStress, TangentIsTheDerivativeOfTheStress) {
  expect_tangent_is_the_derivative<2>();
  expect_tangent_is_the_derivative<3>();
}

// A rigid step (F_n = Q F_{n-1}, so C_n = C_{n-1}) takes the limit Sigma = S(C_m): Pi = F_m S(C)
// with S(C) = F^-1 P(F), and the energy identity holds with both sides zero.
template <int d> void expect_rigid_step_limit() {
  std::mt19937 rng(3);
  for (const Law& law : laws<d>()) {
    SCOPED_TRACE(describe<d>(*law));
    for (int sample = 0; sample < 20; ++sample) {
      const Tensor<d> F0 = random_gradient<d>(rng), F1 = random_rotation<d>(rng) * F0;
      const double W0 = energy<d>(*law, F0);
      const StepResponse s = step_response(*law, AlgorithmicStress::gonzalez, F0, W0, F1);
      const Tensor<d> S = F0.inverse() * piola_response(*law, F0).stress;
      const Tensor<d> expected = 0.5 * (F0 + F1) * S;
      EXPECT_LT((s.stress - expected).norm(), 1e-12 * expected.norm());
      EXPECT_NEAR(contract<d>(s.stress, F1 - F0), 0.0, 1e-12 * expected.norm() * F0.norm());
    }
  }
}

TEST(GonzalezStress, RigidStepTakesTheLimit) {
  expect_rigid_step_limit<2>();
  expect_rigid_step_limit<3>();
}

// Pi F_m^T symmetric: the internal forces of the step have no moment, so the midpoint rule keeps
// the angular momentum with either stress. Close to a continuous path both give the midpoint
// stress to second order.
template <int d> void expect_no_moment_and_consistency() {
  std::mt19937 rng(23);
  const CiarletGeymonat law(0.5, 0.005, 0.35);
  for (int sample = 0; sample < 30; ++sample) {
    const Tensor<d> F0 = random_gradient<d>(rng), F1 = large_step<d>(law, F0, rng);
    const double W0 = energy<d>(law, F0);
    for (AlgorithmicStress kind : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint}) {
      const Tensor<d> moment =
          step_response(law, kind, F0, W0, F1).stress * (0.5 * (F0 + F1)).transpose();
      EXPECT_LT((moment - moment.transpose()).norm(), 1e-13 * moment.norm());
    }
    const Tensor<d> G = normal_tensor<d>(rng);
    double previous = 0;
    for (double h : {1e-2, 5e-3}) {
      const Tensor<d> Fh = F0 + h * G;
      const double gap = (step_response(law, AlgorithmicStress::gonzalez, F0, W0, Fh).stress -
                          step_response(law, AlgorithmicStress::midpoint, F0, W0, Fh).stress)
                             .norm();
      if (previous > 0) {
        EXPECT_LT(gap, 0.3 * previous); // O(h^2): halving h quarters it
      }
      previous = gap;
    }
  }
}

TEST(StepStress, ConservesAngularMomentumAndIsConsistent) {
  expect_no_moment_and_consistency<2>();
  expect_no_moment_and_consistency<3>();
}

// Plane strain is the 3D formula at F33 = 1 on both ends of the step (dC33 = 0): the 2D step's
// stress, tangent and energy are the in-plane blocks of the 3D step's.
TEST(StepStress, PlaneStrainIsTheThreeDimensionalStepAtUnitF33) {
  std::mt19937 rng(31);
  constexpr int in_plane[4] = {0, 1, 3, 4};
  const CiarletGeymonat law(0.5, 0.005, 0.35, PlaneMode::strain);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix2d F0 = random_gradient<2>(rng), F1 = large_step<2>(law, F0, rng);
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

// The 2D material point is the law W(C) of the 2D response: P = F S, W equal.
TEST(HyperelasticLaw, InPlanePointMatchesTheResponse) {
  std::mt19937 rng(31);
  for (const Law& law : laws<2>()) {
    SCOPED_TRACE(describe<2>(*law));
    for (int sample = 0; sample < 20; ++sample) {
      const Eigen::Matrix2d F = random_gradient<2>(rng);
      const HyperelasticResponse r = law->response(F);
      const MaterialPoint2d p = law->in_plane(F.transpose() * F);
      EXPECT_NEAR(p.energy, r.energy, 1e-13 * std::abs(r.energy) + 1e-15);
      EXPECT_LT((F * p.S - r.stress).norm(), 1e-12 * r.stress.norm() + 1e-15);
    }
  }
}

TEST(StepStress, NamesRoundTripAndUnknownIsRefused) {
  for (AlgorithmicStress s : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint})
    EXPECT_EQ(algorithmic_stress_named(to_string(s)), s);
  EXPECT_THROW(algorithmic_stress_named("simo"), Error);
}

} // namespace
} // namespace sig
