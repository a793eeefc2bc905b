#pragma once
// The 2D Hertz contact of a cylinder on a rigid plane (thesis (7.38)), the analytic reference
// of scene 7a: a half disc of radius R loaded by the traction f on its top edge (total load
// 2 R f per unit thickness) pressed onto the foundation. Plane strain:
//   b    = 2 sqrt(2 R^2 f (1 - nu^2) / (E pi))        contact half-width
//   p(x) = 4 R f / (pi b^2) sqrt(b^2 - x^2)            pressure, 0 for |x| >= b
//   p0   = 4 R f / (pi b)                              peak pressure at x = 0
#include <span>

namespace sig {

struct HertzData {
  double radius = 8;
  double traction = 2; ///< f, magnitude of the vertical traction on the top edge
  double young = 150;
  double poisson = 0.3;
};

double hertz_half_width(const HertzData& data);
double hertz_peak_pressure(const HertzData& data);
/// p(x) with x measured from the centre line of the disc.
double hertz_pressure(const HertzData& data, double x);

/// One contact node as post-processing sees it.
struct PressureSample {
  double x = 0;        ///< x1 relative to the centre line
  double pressure = 0; ///< nodal multiplier / weight
  double weight = 0;   ///< tributary length on Gamma3
  bool contact = false;
};

/// The discrete pressure against Hertz.
struct PressureError {
  double p_max = 0;            ///< largest nodal pressure
  double p_max_rel_error = 0;  ///< (p_max - p0) / p0, signed
  double half_width = 0;       ///< max |x| over nodes with status contact
  double half_width_error = 0; ///< (half_width - b) / b, signed
  double l2_rel_error = 0;     ///< sqrt(sum w (p - p_H)^2) / sqrt(sum w p_H^2) over Gamma3
};

PressureError hertz_pressure_error(const HertzData& data, std::span<const PressureSample> nodes);

} // namespace sig
