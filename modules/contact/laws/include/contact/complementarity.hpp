#pragma once
// Scalar kernels of the contact and friction laws: each value sits next to its generalized
// derivative, and every formula carries the thesis equation it comes from. The per-node kernel
// (contact_kernel.hpp) builds Alart-Curnier's functions, the methods' tests and their generalized
// Jacobians from these and nothing else (STYLE.md 2).
//
// Variables: q the penetration of a node beyond the obstacle surface (contact_law.hpp), z a trial
// tangential pressure, s >= 0 a slip bound.
//
// Kink convention: [x]_+ = max(x, 0) with generalized derivative 1 at x >= 0, i.e. the kink
// belongs to the active (contact) side. The thesis's derivative (3.23)-(3.26) puts the kink on
// the inactive side (active if lambda + gamma u_n > 0), but its active-set test (step (ii) after
// (3.29) and after (7.19)) uses >= 0; we follow the active-set test so that the derivative of
// every kernel is the derivative of the branch the active-set test selects. Likewise |z| = s
// belongs to the stick side, and a truncation's kink to its plateau.
#include <cmath>

namespace sig {

/// \f$ [x]_+ = \max(x, 0) \f$, the projection onto \f$\mathbb{R}_+\f$ (thesis (1.21)).
inline double positive_part(double x) {
  return x > 0 ? x : 0.0;
}

/// Generalized derivative of \f$[x]_+\f$: \f$ 1 \f$ for \f$ x \ge 0 \f$, \f$ 0 \f$ otherwise
/// (the kink at 0 belongs to the active side).
inline double d_positive_part(double x) {
  return x >= 0 ? 1.0 : 0.0;
}

// --- Normal compliance ------------------------------------------------------------------------

/// Normal compliance (1.24), \f$ -\sigma_n = p(q) = c_n [q]_+ \f$: the deformable foundation
/// responds from the obstacle surface, q = 0.
inline double normal_compliance(double q, double cn) {
  return cn * positive_part(q);
}
/// \f$ dp/dq = c_n H(q) \f$, with \f$H(0) = 1\f$.
inline double d_normal_compliance(double q, double cn) {
  return cn * d_positive_part(q);
}

/// Truncated normal compliance of chapter 6: \f$ p = \min(c_n [q]_+, c_3) \f$, c_3 > 0.
inline double truncated_normal_compliance(double q, double cn, double c3) {
  const double p = normal_compliance(q, cn);
  return p < c3 ? p : c3;
}
/// \f$ dp/dq \f$: \f$ c_n \f$ on \f$ q \ge 0 \f$ below the cap, 0 on the plateau; the cap's kink
/// \f$ c_n q = c_3 \f$ belongs to the plateau.
inline double d_truncated_normal_compliance(double q, double cn, double c3) {
  return normal_compliance(q, cn) < c3 ? d_normal_compliance(q, cn) : 0.0;
}

// --- The specific penalty of [62] (thesis (3.51), (8.32)) -------------------------------------
// The normal compliance over a time step from the penetration a at its start to b at its end is
// c_n p(a, b), the secant of the potential [.]_+^2 / 2,
//     p(a, b) = ([b]_+^2 - [a]_+^2) / (2 (b - a)),   p(a, a) = [a]_+ (the limit b -> a),
// so its work over the step, c_n p(a, b) (b - a), is exactly the change of the potential
// (c_n / 2)([b]_+^2 - [a]_+^2) and the midpoint rule conserves E + the foundation's energy (3.53).
// Written by cases so that no branch divides by a small b - a: both positive gives the mean
// (a + b) / 2; one positive value s and one non-positive t give s^2 / (2 (s - t)), whose
// denominator is at least s. p is continuous, non-decreasing in b, and C1 except at a <= 0,
// b = 0 (where it starts from 0 with slope 0 for a < 0, 1/2 for a = 0).

/// p(a, b) of (3.51): a, b the penetrations at the start and at the end of the time step.
inline double specific_penalty(double a, double b) {
  if (a > 0 && b > 0) return 0.5 * (a + b);
  if (b > 0) return b * b / (2 * (b - a)); // a <= 0 < b
  if (a > 0) return a * a / (2 * (a - b)); // b <= 0 < a
  return 0.0;
}

/// dp/db, >= 0: the generalized Jacobian of the force at the end of the step (b <= 0 with
/// a <= 0 gives 0).
inline double d_specific_penalty(double a, double b) {
  if (a > 0 && b > 0) return 0.5;
  if (b > 0) return b * (b - 2 * a) / (2 * (b - a) * (b - a));
  if (a > 0) return a * a / (2 * (a - b) * (a - b));
  return 0.0;
}

// --- Friction (2D: the ball of radius s is the interval [-s, s]) ------------------------------

/// \f$ \mathrm{proj}_{[-s, s]}(z) \f$, s >= 0: the tangential pressure of a node whose trial
/// pressure z = t + r q_t meets the slip bound s (the projection of (3.19), 3rd row).
inline double project_interval(double z, double s) {
  return z > s ? s : (z < -s ? -s : z);
}
/// \f$ \partial\,\mathrm{proj} / \partial z \f$: 1 inside, 0 beyond the bound; the kink
/// |z| = s belongs to the inside (stick), as [x]_+'s kink belongs to contact.
inline double d_project_interval_dz(double z, double s) {
  return std::abs(z) <= s ? 1.0 : 0.0;
}
/// \f$ \partial\,\mathrm{proj} / \partial s \f$: sign(z) beyond the bound (slip), 0 inside.
inline double d_project_interval_ds(double z, double s) {
  return std::abs(z) <= s ? 0.0 : (z > 0 ? 1.0 : -1.0);
}

} // namespace sig
