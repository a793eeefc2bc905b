#include "post/hertz.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sig {

double hertz_half_width(const HertzData& d) {
  const double r2 = d.radius * d.radius;
  return 2 * std::sqrt(2 * r2 * d.traction * (1 - d.poisson * d.poisson) /
                       (d.young * std::numbers::pi));
}

double hertz_peak_pressure(const HertzData& d) {
  return 4 * d.radius * d.traction / (std::numbers::pi * hertz_half_width(d));
}

double hertz_pressure(const HertzData& d, double x) {
  const double b = hertz_half_width(d);
  if (std::abs(x) >= b) return 0.0;
  return 4 * d.radius * d.traction / (std::numbers::pi * b * b) * std::sqrt(b * b - x * x);
}

PressureError hertz_pressure_error(const HertzData& data, std::span<const PressureSample> nodes) {
  SIG_VERIFY(!nodes.empty(), "Hertz comparison: no contact nodes");
  const double b = hertz_half_width(data);
  const double p0 = hertz_peak_pressure(data);
  PressureError e;
  double error2 = 0, norm2 = 0;
  for (const auto& n : nodes) {
    const double exact = hertz_pressure(data, n.x);
    e.p_max = std::max(e.p_max, n.pressure);
    if (n.contact) e.half_width = std::max(e.half_width, std::abs(n.x));
    error2 += n.weight * (n.pressure - exact) * (n.pressure - exact);
    norm2 += n.weight * exact * exact;
  }
  SIG_VERIFY(norm2 > 0, "Hertz comparison: no node with positive weight inside |x| < b = " << b);
  e.p_max_rel_error = (e.p_max - p0) / p0;
  e.half_width_error = (e.half_width - b) / b;
  e.l2_rel_error = std::sqrt(error2 / norm2);
  return e;
}

} // namespace sig
