#include "post/hertz_sphere.hpp"

#include "core/error.hpp"

#include <cmath>
#include <numbers>

namespace sig {

double effective_modulus(const HertzSphere& d) {
  return d.young / (1 - d.poisson * d.poisson);
}

double contact_radius(const HertzSphere& d) {
  return std::cbrt(3 * d.load * d.radius / (4 * effective_modulus(d)));
}

double peak_pressure(const HertzSphere& d) {
  const double a = contact_radius(d);
  return 3 * d.load / (2 * std::numbers::pi * a * a);
}

double pressure_at(const HertzSphere& d, double r) {
  const double a = contact_radius(d);
  return std::abs(r) >= a ? 0.0 : peak_pressure(d) * std::sqrt(1 - r * r / (a * a));
}

double approach(const HertzSphere& d) {
  const double a = contact_radius(d);
  return a * a / d.radius;
}

double stick_radius(const HertzSphere& d, double friction, double tangential_load) {
  SIG_VERIFY(friction > 0 && tangential_load >= 0 && tangential_load <= friction * d.load,
             "Cattaneo-Mindlin: the tangential load Q = "
                 << tangential_load << " must lie in [0, mu P] = [0, " << friction * d.load << "]");
  return contact_radius(d) * std::cbrt(1 - tangential_load / (friction * d.load));
}

double tangential_traction_at(const HertzSphere& d, double friction, double tangential_load,
                              double r) {
  const double a = contact_radius(d), c = stick_radius(d, friction, tangential_load);
  r = std::abs(r);
  if (r >= a) return 0.0;
  const double scale = friction * peak_pressure(d) / a;
  const double full = scale * std::sqrt(a * a - r * r);
  return r < c ? full - scale * std::sqrt(c * c - r * r) : full;
}

double dundurs_beta_on_rigid(double poisson) {
  return (1 - 2 * poisson) / (2 * (1 - poisson));
}

} // namespace sig
