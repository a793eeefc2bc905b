// Complementarity kernels: every generalized derivative against finite differences on both sides
// of every kink (offsets 1e-8 ... 1, parameters over several decades; central differences off the
// kink, one-sided into the active side at it), and the value identities: the zeros of the
// Alart-Curnier and projection functions are exactly the Signorini states (1.22).
#include "contact/complementarity.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace sig {
namespace {

using Scalar1 = std::function<double(double)>;
using Scalar2 = std::function<double(double, double)>; // (lambda, un)

const std::vector<double> kOffsets = {1e-8, 1e-6, 1e-4, 1e-2, 1.0};
const std::vector<double> kParameters = {1e-2, 1.0, 1e2, 1e4}; // r, gamma, c, c_n
const std::vector<double> kGaps = {0.0, 0.5, 3.0};
constexpr double kEps = std::numeric_limits<double>::epsilon();

// A finite difference of a piecewise linear function is exact up to the roundoff of its
// operands (of size `scale`) divided by the step.
double tolerance(double derivative, double scale, double h) {
  return 1e-7 * (1 + std::abs(derivative)) + 8 * kEps * scale / h;
}

// f, df near a kink at x0 of f; `up_is_active`: the side x > x0 is the one the kink belongs to.
void check_1d(const Scalar1& f, const Scalar1& df, double x0, double slope_scale,
              bool up_is_active) {
  const double scale = slope_scale * (1 + std::abs(x0));
  for (double delta : kOffsets)
    for (double side : {-1.0, 1.0}) {
      const double x = x0 + side * delta;
      const double h = delta / 4;
      const double fd = (f(x + h) - f(x - h)) / (2 * h);
      EXPECT_NEAR(df(x), fd, tolerance(df(x), scale, h))
          << "x0 " << x0 << " offset " << side * delta;
    }
  // At the kink: the derivative is the one of the active side.
  const double active = up_is_active ? 1.0 : -1.0;
  for (double h : {1e-8, 1e-4}) {
    const double one_sided = (f(x0 + active * h) - f(x0)) / (active * h);
    EXPECT_NEAR(df(x0), one_sided, tolerance(df(x0), scale, h)) << "kink " << x0 << " h " << h;
  }
}

// f(lambda, un) with a kink on the line activity(lambda, un) = a_lambda lambda + a_un un + a0 = 0
// (a_lambda, a_un > 0), the side activity >= 0 being active. Base points on the kink line, then
// steps off it along lambda by +-delta / a_lambda.
void check_2d(const Scalar2& f, const Scalar2& df_dlambda, const Scalar2& df_dun, double a_lambda,
              double a_un, const Scalar2& activity, double g) {
  for (double t : {-1.0, -1e-3, 0.0, 1e-3, 2.0}) {
    const double un = g + t;
    // The smallest lambda on the active side: the kink in floating point.
    double lambda0 = -activity(0.0, un) / a_lambda;
    while (activity(lambda0, un) < 0)
      lambda0 = std::nextafter(lambda0, INFINITY);
    while (activity(std::nextafter(lambda0, -INFINITY), un) >= 0)
      lambda0 = std::nextafter(lambda0, -INFINITY);
    const double scale = std::max({1.0, std::abs(lambda0) * a_lambda, std::abs(un) * a_un,
                                   std::abs(g) * a_un, std::abs(lambda0), std::abs(un)});
    for (double delta : kOffsets)
      for (double side : {-1.0, 1.0}) {
        const double lambda = lambda0 + side * delta / a_lambda;
        const double hl = delta / (4 * a_lambda), hu = delta / (4 * a_un);
        const double fd_l = (f(lambda + hl, un) - f(lambda - hl, un)) / (2 * hl);
        const double fd_u = (f(lambda, un + hu) - f(lambda, un - hu)) / (2 * hu);
        const double dl = df_dlambda(lambda, un), du = df_dun(lambda, un);
        EXPECT_NEAR(dl, fd_l, tolerance(dl, scale, hl))
            << "d/dlambda at un " << un << " offset " << side * delta;
        EXPECT_NEAR(du, fd_u, tolerance(du, scale, hu))
            << "d/dun at un " << un << " offset " << side * delta;
      }
    // On the kink: one-sided differences into the active side (a increases with both).
    const double hl = 1e-6 / a_lambda, hu = 1e-6 / a_un;
    const double dl = df_dlambda(lambda0, un), du = df_dun(lambda0, un);
    EXPECT_NEAR(dl, (f(lambda0 + hl, un) - f(lambda0, un)) / hl, tolerance(dl, scale, hl))
        << "kink d/dlambda at un " << un;
    EXPECT_NEAR(du, (f(lambda0, un + hu) - f(lambda0, un)) / hu, tolerance(du, scale, hu))
        << "kink d/dun at un " << un;
  }
}

TEST(Complementarity, PositivePartDerivative) {
  EXPECT_EQ(positive_part(-2.0), 0.0);
  EXPECT_EQ(positive_part(0.0), 0.0);
  EXPECT_EQ(positive_part(3.5), 3.5);
  EXPECT_EQ(d_positive_part(0.0), 1.0); // the kink belongs to the active side
  EXPECT_EQ(d_positive_part(-1e-300), 0.0);
  check_1d(positive_part, d_positive_part, 0.0, 1.0, true);
}

TEST(Complementarity, AlartCurnierDerivatives) {
  for (double r : kParameters)
    for (double g : kGaps) {
      SCOPED_TRACE(testing::Message() << "r " << r << " g " << g);
      check_2d([&](double l, double u) { return alart_curnier_normal(l, u, g, r); },
               [&](double l, double u) { return d_alart_curnier_normal_d_lambda(l, u, g, r); },
               [&](double l, double u) { return d_alart_curnier_normal_d_un(l, u, g, r); }, 1.0, r,
               [&](double l, double u) { return l + r * (u - g); }, g);
    }
}

TEST(Complementarity, ProjectionDerivatives) {
  for (double c : kParameters)
    for (double g : kGaps) {
      SCOPED_TRACE(testing::Message() << "c " << c << " g " << g);
      check_2d([&](double l, double u) { return projection_residual(l, u, g, c); },
               [&](double l, double u) { return d_projection_residual_d_lambda(l, u, g, c); },
               [&](double l, double u) { return d_projection_residual_d_un(l, u, g, c); }, c, 1.0,
               [&](double l, double u) { return (u - g) + c * l; }, g);
    }
}

TEST(Complementarity, PenaltyAndComplianceDerivatives) {
  for (double r : kParameters)
    for (double g : kGaps) {
      SCOPED_TRACE(testing::Message() << "r " << r << " g " << g);
      check_1d([&](double un) { return penalty_force(un, g, r); },
               [&](double un) { return d_penalty_force(un, g, r); }, g, r, true);
      check_1d([&](double un) { return normal_compliance(un, g, r); },
               [&](double un) { return d_normal_compliance(un, g, r); }, g, r, true);
      // Truncated compliance: kinks at g (contact) and where c_n (u_n - g) = c_3 (plateau).
      const double c3 = 0.7 * r;
      const auto p = [&](double un) { return truncated_normal_compliance(un, g, r, c3); };
      const auto dp = [&](double un) { return d_truncated_normal_compliance(un, g, r, c3); };
      check_1d(p, dp, g, r, true);
      double cap = g + c3 / r; // the first u_n on the plateau, in floating point
      while (normal_compliance(cap, g, r) < c3)
        cap = std::nextafter(cap, INFINITY);
      check_1d(p, dp, cap, r, true);
    }
}

TEST(Complementarity, ComplianceValues) {
  EXPECT_DOUBLE_EQ(normal_compliance(0.75, 0.5, 10), 2.5);
  EXPECT_EQ(normal_compliance(0.25, 0.5, 10), 0.0);
  EXPECT_DOUBLE_EQ(penalty_force(1.5, 0.5, 1e3), 1e3);
  EXPECT_EQ(truncated_normal_compliance(0.625, 0.5, 10, 1), 1.0);    // capped at c3
  EXPECT_EQ(truncated_normal_compliance(0.5625, 0.5, 10, 1), 0.625); // below the cap
  EXPECT_EQ(truncated_normal_compliance(0.25, 0.5, 10, 1), 0.0);     // no contact
  EXPECT_EQ(d_truncated_normal_compliance(0.625, 0.5, 10, 1), 0.0);
  EXPECT_EQ(d_truncated_normal_compliance(0.5625, 0.5, 10, 1), 10.0);
  EXPECT_EQ(d_truncated_normal_compliance(0.25, 0.5, 10, 1), 0.0);
}

// Signorini with gap (1.22) on an exactly representable grid.
bool is_signorini_state(double lambda, double un, double g) {
  return un <= g && lambda >= 0 && lambda * (un - g) == 0;
}

TEST(Complementarity, ZerosAreExactlyTheSignoriniStates) {
  const std::vector<double> values = {-1.0, -0.5, -0.125, 0.0, 0.125, 0.5, 1.0};
  int states = 0;
  for (double r : {0.25, 1.0, 100.0, 1e4})
    for (double g : {0.0, 0.25, 2.0})
      for (double lambda : values)
        for (double s : values) {
          const double un = g + s;
          const bool state = is_signorini_state(lambda, un, g);
          states += state;
          EXPECT_EQ(alart_curnier_normal(lambda, un, g, r) == 0, state)
              << "AC r " << r << " lambda " << lambda << " un-g " << s;
          EXPECT_EQ(projection_residual(lambda, un, g, r) == 0, state)
              << "projection c " << r << " lambda " << lambda << " un-g " << s;
          // At a Signorini state the active-set tests agree with the contact status: a node
          // carrying force is active, a node off the obstacle is inactive.
          if (state && lambda > 0) {
            EXPECT_TRUE(pdas_is_active(lambda, un, g, r));
            EXPECT_TRUE(projection_is_active(lambda, un, g, r));
          }
          if (state && un < g) {
            EXPECT_FALSE(pdas_is_active(lambda, un, g, r));
            EXPECT_FALSE(projection_is_active(lambda, un, g, r));
          }
        }
  EXPECT_GT(states, 0);
}

TEST(Complementarity, MinMaxForms) {
  // C = min(lambda, -r (un - g)) and P = max(un - g, -c lambda): the documented identities.
  for (double r : {1e-2, 1.0, 1e3})
    for (double lambda : {-2.0, -0.3, 0.0, 0.7, 5.0})
      for (double s : {-1.5, -0.01, 0.0, 0.02, 4.0}) {
        const double g = 0.5, un = g + s;
        EXPECT_NEAR(alart_curnier_normal(lambda, un, g, r), std::min(lambda, -r * (un - g)),
                    1e-12 * (1 + r));
        EXPECT_NEAR(projection_residual(lambda, un, g, r), std::max(un - g, -r * lambda),
                    1e-12 * (1 + r));
      }
}

TEST(Complementarity, DerivativesFollowTheActiveSetTests) {
  // The generalized derivative is the active branch exactly when the active-set test says so,
  // the kink included.
  for (double r : {0.25, 1.0, 1024.0}) // exact products and quotients below
    for (double lambda : {-1.0, 0.0, 0.5})
      for (double s : {-0.5, 0.0, 0.25}) {
        const double g = 0.125, un = g + s;
        EXPECT_EQ(d_alart_curnier_normal_d_un(lambda, un, g, r) == -r,
                  pdas_is_active(lambda, un, g, r));
        EXPECT_EQ(d_projection_residual_d_un(lambda, un, g, r) == 1,
                  projection_is_active(lambda, un, g, r));
        // On the kink itself.
        EXPECT_TRUE(pdas_is_active(-r * s, un, g, r));
        EXPECT_EQ(d_alart_curnier_normal_d_un(-r * s, un, g, r), -r);
        EXPECT_TRUE(projection_is_active(-s / r, un, g, r));
        EXPECT_EQ(d_projection_residual_d_lambda(-s / r, un, g, r), 0.0);
      }
}

} // namespace
} // namespace sig
