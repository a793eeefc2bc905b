// Hertz reference (thesis (7.38)): values of scene 7a, equilibrium of the pressure, and the
// discrete error measures on sampled profiles.
#include "post/hertz.hpp"

#include "core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace sig {
namespace {

const HertzData kScene7a{8.0, 2.0, 150.0, 0.3};

// Nodes spaced h apart on [-L, L], trapezoid weights, pressure `scale` times Hertz's.
std::vector<PressureSample> sampled(const HertzData& d, double scale, int n, double L) {
  std::vector<PressureSample> nodes;
  const double h = 2 * L / n;
  for (int i = 0; i <= n; ++i) {
    const double x = -L + i * h;
    const double p = scale * hertz_pressure(d, x);
    nodes.push_back({x, p, (i == 0 || i == n) ? h / 2 : h, p > 0});
  }
  return nodes;
}

TEST(Hertz, Scene7aHalfWidthAndPeakPressure) {
  // By hand: b = 2 sqrt(2 * 64 * 2 * 0.91 / (150 pi)) = 2 sqrt(0.494351) = 1.40621;
  // p0 = 4 * 8 * 2 / (pi * 1.40621) = 14.4871. Thesis: 1.406 and 14.49.
  EXPECT_NEAR(hertz_half_width(kScene7a), 1.40621, 1e-5);
  EXPECT_NEAR(hertz_peak_pressure(kScene7a), 14.4871, 1e-4);
  EXPECT_DOUBLE_EQ(hertz_pressure(kScene7a, 0.0), hertz_peak_pressure(kScene7a));
}

TEST(Hertz, PressureVanishesOutsideTheContactZone) {
  const double b = hertz_half_width(kScene7a);
  EXPECT_EQ(hertz_pressure(kScene7a, b), 0.0);
  EXPECT_EQ(hertz_pressure(kScene7a, -1.5 * b), 0.0);
  EXPECT_GT(hertz_pressure(kScene7a, 0.99 * b), 0.0);
  EXPECT_DOUBLE_EQ(hertz_pressure(kScene7a, 0.3), hertz_pressure(kScene7a, -0.3));
}

TEST(Hertz, PressureBalancesTheLoadOnTheTopEdge) {
  // The elliptic profile integrates to pi b p0 / 2, which must equal the total load 2 R f.
  for (const HertzData d : {kScene7a, HertzData{3.0, 0.5, 70.0, 0.25}}) {
    const double b = hertz_half_width(d);
    EXPECT_NEAR(std::numbers::pi * b * hertz_peak_pressure(d) / 2, 2 * d.radius * d.traction,
                1e-12 * d.radius * d.traction);
    double load = 0;
    for (const auto& node : sampled(d, 1.0, 20000, 2 * b))
      load += node.weight * node.pressure;
    EXPECT_NEAR(load, 2 * d.radius * d.traction, 1e-4 * d.radius * d.traction);
  }
}

TEST(Hertz, ExactProfileHasNoError) {
  // 401 nodes on [-2b, 2b] include x = 0, so the peak is sampled exactly.
  const double b = hertz_half_width(kScene7a);
  const auto nodes = sampled(kScene7a, 1.0, 400, 2 * b);
  const PressureError e = hertz_pressure_error(kScene7a, nodes);
  EXPECT_NEAR(e.l2_rel_error, 0.0, 1e-14);
  EXPECT_NEAR(e.p_max, hertz_peak_pressure(kScene7a), 1e-12);
  EXPECT_NEAR(e.p_max_rel_error, 0.0, 1e-14);
  // The outermost contact node lies within one spacing h = b / 100 inside b.
  EXPECT_LT(e.half_width, b);
  EXPECT_GE(e.half_width, b - b / 100 - 1e-12);
  // So the relative half-width error lies in [-h / b, 0) = [-0.01, 0).
  EXPECT_LT(e.half_width_error, 0.0);
  EXPECT_GE(e.half_width_error, -0.01 - 1e-12);
}

TEST(Hertz, ScaledProfileGivesTheScaleAsError) {
  const double b = hertz_half_width(kScene7a);
  const PressureError e = hertz_pressure_error(kScene7a, sampled(kScene7a, 1.1, 400, 2 * b));
  EXPECT_NEAR(e.l2_rel_error, 0.1, 1e-12);
  EXPECT_NEAR(e.p_max_rel_error, 0.1, 1e-12);
}

TEST(Hertz, HalfWidthCountsContactNodesOnly) {
  // A node marked free carries no weight in the half-width even far out, a contact node does.
  std::vector<PressureSample> nodes = {{0.0, 14.0, 0.1, true},
                                       {1.0, 3.0, 0.1, true},
                                       {-1.2, 1.0, 0.1, true},
                                       {3.0, 0.0, 0.1, false}};
  EXPECT_DOUBLE_EQ(hertz_pressure_error(kScene7a, nodes).half_width, 1.2);
  nodes[3].contact = true;
  EXPECT_DOUBLE_EQ(hertz_pressure_error(kScene7a, nodes).half_width, 3.0);
}

TEST(Hertz, NoNodesIsAnError) {
  EXPECT_THROW(hertz_pressure_error(kScene7a, std::vector<PressureSample>{}), Error);
}

} // namespace
} // namespace sig
