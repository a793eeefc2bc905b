// The scalar kernels of complementarity.hpp: every generalized derivative against finite
// differences on both sides of every kink (offsets 1e-8 ... 1, parameters over several decades;
// central differences off the kink, one-sided into the side that owns it at it). The per-node
// Alart-Curnier kernel built on them is tested in test_contact_kernel.cpp.
#include "contact/complementarity.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace sig {
namespace {

using Scalar1 = std::function<double(double)>;

const std::vector<double> kOffsets = {1e-8, 1e-6, 1e-4, 1e-2, 1.0};
const std::vector<double> kParameters = {1e-2, 1.0, 1e2, 1e4}; // c_n
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

TEST(Complementarity, PositivePartDerivative) {
  EXPECT_EQ(positive_part(-2.0), 0.0);
  EXPECT_EQ(positive_part(0.0), 0.0);
  EXPECT_EQ(positive_part(3.5), 3.5);
  EXPECT_EQ(d_positive_part(0.0), 1.0); // the kink belongs to the active side
  EXPECT_EQ(d_positive_part(-1e-300), 0.0);
  check_1d(positive_part, d_positive_part, 0.0, 1.0, true);
}

TEST(Complementarity, ComplianceDerivatives) {
  for (double cn : kParameters) {
    SCOPED_TRACE(testing::Message() << "cn " << cn);
    check_1d([&](double q) { return normal_compliance(q, cn); },
             [&](double q) { return d_normal_compliance(q, cn); }, 0.0, cn, true);
    // Truncated compliance: kinks at 0 (contact) and where c_n q = c_3 (plateau).
    const double c3 = 0.7 * cn;
    const auto p = [&](double q) { return truncated_normal_compliance(q, cn, c3); };
    const auto dp = [&](double q) { return d_truncated_normal_compliance(q, cn, c3); };
    check_1d(p, dp, 0.0, cn, true);
    double cap = c3 / cn; // the first q on the plateau, in floating point
    while (normal_compliance(cap, cn) < c3)
      cap = std::nextafter(cap, INFINITY);
    check_1d(p, dp, cap, cn, true);
  }
}

TEST(Complementarity, ComplianceValues) {
  EXPECT_DOUBLE_EQ(normal_compliance(0.25, 10), 2.5);
  EXPECT_EQ(normal_compliance(-0.25, 10), 0.0);
  EXPECT_EQ(truncated_normal_compliance(0.125, 10, 1), 1.0);    // capped at c3
  EXPECT_EQ(truncated_normal_compliance(0.0625, 10, 1), 0.625); // below the cap
  EXPECT_EQ(truncated_normal_compliance(-0.25, 10, 1), 0.0);    // no contact
  EXPECT_EQ(d_truncated_normal_compliance(0.125, 10, 1), 0.0);
  EXPECT_EQ(d_truncated_normal_compliance(0.0625, 10, 1), 10.0);
  EXPECT_EQ(d_truncated_normal_compliance(-0.25, 10, 1), 0.0);
}

TEST(Complementarity, ProjectionOnTheSlipIntervalDerivatives) {
  // Kinks at z = +-s: the inside (stick) owns them, so the one-sided difference into it.
  for (double s : {1e-2, 1.0, 1e2, 1e4}) {
    SCOPED_TRACE(testing::Message() << "s " << s);
    const auto p = [&](double z) { return project_interval(z, s); };
    const auto dp = [&](double z) { return d_project_interval_dz(z, s); };
    check_1d(p, dp, s, 1.0, false);
    check_1d(p, dp, -s, 1.0, true);
    // In s: slope sign(z) beyond the bound, 0 inside; off the kink |z| = s.
    for (double z : {-3 * s, -0.5 * s, 0.0, 0.25 * s, 2 * s}) {
      const double h = 1e-6 * s;
      const double fd = (project_interval(z, s + h) - project_interval(z, s - h)) / (2 * h);
      EXPECT_NEAR(d_project_interval_ds(z, s), fd, 1e-7) << "z " << z;
    }
  }
  EXPECT_EQ(project_interval(5.0, 2.0), 2.0);
  EXPECT_EQ(project_interval(-5.0, 2.0), -2.0);
  EXPECT_EQ(project_interval(1.5, 2.0), 1.5);
  EXPECT_EQ(project_interval(0.3, 0.0), 0.0); // a zero bound: frictionless
  EXPECT_EQ(d_project_interval_ds(0.0, 0.0), 0.0);
}

} // namespace
} // namespace sig
