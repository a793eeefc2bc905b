#pragma once
// Deformation gradients for the material tests: rotations, and random F = R(theta1) diag(s1, s2)
// R(theta2) with det F uniform in a range and a bounded stretch ratio.
#include "material/hyperelastic.hpp"

#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace sig::test {

inline std::string describe(const HyperelasticLaw& law) {
  return law.name() + (law.plane() == PlaneMode::strain ? " plane strain" : " plane stress");
}

inline Eigen::Matrix2d rotation(double theta) {
  Eigen::Matrix2d q;
  q << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return q;
}

/// det F uniform in [det_low, det_high], the stretch ratio s1 / s2 = exp(2 x), x uniform in
/// [-log_ratio, log_ratio].
inline Eigen::Matrix2d random_gradient(std::mt19937& rng, double det_low, double det_high,
                                       double log_ratio) {
  std::uniform_real_distribution<double> det(det_low, det_high), angle(0.0, 2 * std::numbers::pi),
      ratio(-log_ratio, log_ratio);
  const double d = det(rng), r = std::exp(ratio(rng));
  const Eigen::Vector2d s(std::sqrt(d) * r, std::sqrt(d) / r);
  return rotation(angle(rng)) * s.asDiagonal() * rotation(angle(rng));
}

} // namespace sig::test
