// The 3D Hertz and Cattaneo-Mindlin references (post/hertz_sphere.hpp) against identities
// they must satisfy that are not their formulas: the pressure integrates to the load and the
// tangential traction to the tangential load (quadrature), the approach and the peak pressure
// by Johnson's other forms (4.23, 4.24), the traction within the cone, its slip annulus on it.
#include "core/error.hpp"
#include "post/hertz_sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace sig {
namespace {

const HertzSphere kBall{/*radius=*/8.0, /*load=*/3.0, /*young=*/150.0, /*poisson=*/0.3};

/// int_0^a f(r) 2 pi r dr with r = a sin(theta), which takes the square-root edge away.
double over_the_disc(double a, const std::function<double(double)>& f) {
  const int n = 20000;
  const double h = std::numbers::pi / 2 / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * h, r = a * std::sin(theta);
    sum += f(r) * 2 * std::numbers::pi * r * a * std::cos(theta) * h;
  }
  return sum;
}

TEST(HertzSphere, ThePressureCarriesTheLoad) {
  const double a = contact_radius(kBall);
  EXPECT_NEAR(over_the_disc(a, [](double r) { return pressure_at(kBall, r); }), kBall.load,
              1e-8 * kBall.load);
  EXPECT_EQ(pressure_at(kBall, a), 0.0);
  EXPECT_EQ(pressure_at(kBall, 0.0), peak_pressure(kBall));
}

TEST(HertzSphere, JohnsonsOtherForms) {
  const double e_star = kBall.young / (1 - kBall.poisson * kBall.poisson);
  const double P = kBall.load, R = kBall.radius;
  EXPECT_NEAR(approach(kBall), std::cbrt(9 * P * P / (16 * R * e_star * e_star)), 1e-14);
  EXPECT_NEAR(peak_pressure(kBall),
              std::cbrt(6 * P * e_star * e_star / (std::pow(std::numbers::pi, 3) * R * R)),
              1e-12 * peak_pressure(kBall));
  // a grows as P^(1/3): twice the load, 2^(1/3) the radius.
  HertzSphere twice = kBall;
  twice.load *= 2;
  EXPECT_NEAR(contact_radius(twice), std::cbrt(2.0) * contact_radius(kBall), 1e-14);
}

TEST(HertzSphere, CattaneoMindlinTractionCarriesTheTangentialLoad) {
  const double mu = 0.4, a = contact_radius(kBall);
  for (double fraction : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const double Q = fraction * mu * kBall.load;
    const double c = stick_radius(kBall, mu, Q);
    EXPECT_NEAR(c, a * std::cbrt(1 - fraction), 1e-14);
    EXPECT_NEAR(over_the_disc(a, [&](double r) { return tangential_traction_at(kBall, mu, Q, r); }),
                Q, 1e-6 * kBall.load)
        << "Q / mu P = " << fraction;
    // Within the cone everywhere, on its edge in the slip annulus c < r < a.
    for (double r = 0; r < a; r += a / 97) {
      const double q = tangential_traction_at(kBall, mu, Q, r), bound = mu * pressure_at(kBall, r);
      EXPECT_LE(q, bound * (1 + 1e-14)) << "r " << r;
      // (sqrt(a^2 - r^2) near the edge: round-off of a^2 - r^2 grows to sqrt(eps) there)
      if (r > c) {
        EXPECT_NEAR(q, bound, 1e-7 * mu * peak_pressure(kBall)) << "r " << r;
      }
    }
  }
  EXPECT_EQ(stick_radius(kBall, mu, 0.0), a);
  EXPECT_EQ(stick_radius(kBall, mu, mu * kBall.load), 0.0);
  EXPECT_THROW(stick_radius(kBall, mu, 1.01 * mu * kBall.load), Error);
  EXPECT_THROW(stick_radius(kBall, mu, -1.0), Error);
}

TEST(HertzSphere, DundursBetaVanishesOnlyForTheIncompressibleBall) {
  EXPECT_EQ(dundurs_beta_on_rigid(0.5), 0.0);
  EXPECT_EQ(dundurs_beta_on_rigid(0.0), 0.5);
  EXPECT_NEAR(dundurs_beta_on_rigid(0.3), 0.4 / 1.4, 1e-15);
}

} // namespace
} // namespace sig
