#pragma once
// The 3D Hertz contact of an elastic sphere on a rigid plane, the analytic reference of the 3D
// Hertz ball (issue 26), and Cattaneo-Mindlin's partial slip under a tangential load after the
// normal one. K. L. Johnson, Contact Mechanics (1985), 4.2 (Hertz) and 7.1 (Cattaneo-Mindlin).
// The plane is rigid, so the effective modulus is the sphere's own, E* = E / (1 - nu^2):
//   a     = (3 P R / (4 E*))^(1/3)                 contact radius
//   p0    = 3 P / (2 pi a^2)                       peak pressure, at the centre
//   p(r)  = p0 sqrt(1 - r^2 / a^2)                 pressure, 0 for r >= a
//   delta = a^2 / R                                approach of the sphere's distant points
// With a tangential load Q < mu P applied after P (no slip as P is applied), the contact sticks
// inside the circle of radius
//   c     = a (1 - Q / (mu P))^(1/3)
// and slips in the annulus c < r < a, with the traction
//   q(r)  = mu p0 / a (sqrt(a^2 - r^2) - [r < c] sqrt(c^2 - r^2)).
// Cattaneo-Mindlin assumes the normal and tangential problems uncoupled: exact for two bodies
// of one material (Dundurs' beta = 0); on a rigid plane beta = (1 - 2 nu) / (2 (1 - nu)), 0 only
// at nu = 0.5, so an elastic sphere with nu < 0.5 follows it approximately (Johnson 7.1).
namespace sig {

struct HertzSphere {
  double radius = 1; ///< R
  double load = 1;   ///< P, the normal force
  double young = 1;  ///< E of the sphere
  double poisson = 0.3;
};

/// E* = E / (1 - nu^2), the plane being rigid.
double effective_modulus(const HertzSphere& data);
double contact_radius(const HertzSphere& data);
double peak_pressure(const HertzSphere& data);
/// p(r), r the distance from the axis of the load.
double pressure_at(const HertzSphere& data, double r);
double approach(const HertzSphere& data);

/// Cattaneo-Mindlin's stick radius c for a tangential load 0 <= Q <= mu P (0 at Q = mu P: the
/// whole contact slides). Throws sig::Error outside that range.
double stick_radius(const HertzSphere& data, double friction, double tangential_load);
/// Its tangential traction q(r).
double tangential_traction_at(const HertzSphere& data, double friction, double tangential_load,
                              double r);
/// Dundurs' beta of an elastic body on a rigid one: (1 - 2 nu) / (2 (1 - nu)).
double dundurs_beta_on_rigid(double poisson);

} // namespace sig
