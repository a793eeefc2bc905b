// The specific penalty kernel p(a, b) of (3.51): its limit b -> a, the secant property (its work
// is the change of the penalty energy), monotonicity and its derivative against finite
// differences on both sides of every kink.
#include "contact/complementarity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sig {
namespace {

double plus_squared(double x) {
  return x > 0 ? x * x : 0.0;
}

TEST(SpecificPenaltyKernel, SecantOfThePenaltyEnergy) {
  for (double a : {-0.7, -1e-3, 0.0, 2e-4, 0.3, 1.5})
    for (double b : {-0.9, -2e-3, 0.0, 1e-4, 0.25, 1.1}) {
      if (a == b) continue;
      // p (b - a) = ([b]_+^2 - [a]_+^2) / 2: the work identity behind (3.53).
      EXPECT_NEAR(specific_penalty(a, b) * (b - a), 0.5 * (plus_squared(b) - plus_squared(a)),
                  1e-15 * (1 + a * a + b * b))
          << a << " " << b;
      EXPECT_GE(specific_penalty(a, b), 0.0);
    }
}

TEST(SpecificPenaltyKernel, LimitAtEqualPenetrationsIsThePositivePart) {
  for (double a : {-0.5, 0.0, 1e-8, 0.2, 3.0}) {
    EXPECT_DOUBLE_EQ(specific_penalty(a, a), std::max(a, 0.0));
    // No cancellation near b = a: exact to rounding a hair away.
    for (double h : {1e-14, 1e-10, 1e-6}) {
      const double expected = a >= 0 ? a + 0.5 * h : 0.0;
      EXPECT_NEAR(specific_penalty(a, a + h), expected, 1e-15 * (1 + std::abs(a))) << a;
    }
  }
}

TEST(SpecificPenaltyKernel, DerivativeMatchesFiniteDifferencesAndIsNonNegative) {
  for (double a : {-0.4, 0.0, 0.3})
    for (double b : {-0.5, -1e-3, 1e-3, 0.2, 0.29, 0.31, 1.0}) {
      if (b == a) continue;
      const double h = 1e-7;
      const double fd = (specific_penalty(a, b + h) - specific_penalty(a, b - h)) / (2 * h);
      EXPECT_NEAR(d_specific_penalty(a, b), fd, 1e-6) << a << " " << b;
      EXPECT_GE(d_specific_penalty(a, b), 0.0);
    }
  // Non-decreasing in b along a fine sweep through the kinks.
  for (double a : {-0.3, 0.0, 0.4}) {
    double previous = specific_penalty(a, -1.0);
    for (int i = 1; i <= 2000; ++i) {
      const double now = specific_penalty(a, -1.0 + 2.0 * i / 2000);
      EXPECT_GE(now, previous - 1e-16);
      previous = now;
    }
  }
}

} // namespace
} // namespace sig
