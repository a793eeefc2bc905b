#pragma once
// Scalar complementarity kernels of the contact and friction laws: each value sits next to its
// generalized derivative, and every formula carries the thesis equation it comes from. Solvers
// build their residuals and generalized Jacobians from these and nothing else (STYLE.md 2).
//
// Variables, per contact node (see contact_elements.hpp):
//   u_n    normal displacement, positive towards the obstacle (u_n = -n . u),
//   g      initial gap, so the Signorini law (1.22) reads u_n <= g, lambda >= 0,
//          lambda (u_n - g) = 0,
//   lambda the nodal contact force (= -sigma_n times the nodal weight), pushing the body along +n.
// The thesis writes these with g = 0 (3.10), (3.20), (7.16); the gap enters as u_n -> u_n - g
// (the change of variable under (1.22)).
//
// Kink convention: [x]_+ = max(x, 0) with generalized derivative 1 at x >= 0, i.e. the kink
// belongs to the active (contact) side. The thesis's derivative (3.23)-(3.26) puts the kink on
// the inactive side (active if lambda + gamma u_n > 0), but its active-set test (step (ii) after
// (3.29) and after (7.19)) uses >= 0; we follow the active-set test so that the derivative of
// every kernel is the derivative of the branch the active-set test selects.
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

// --- Alart-Curnier / primal-dual active set --------------------------------------------------

/// Thesis (3.10) second row, (3.21) \f$R^\lambda\f$, with gap:
/// \f$ C(\lambda, u_n) = \lambda - [\lambda + r (u_n - g)]_+ = \min(\lambda, -r (u_n - g)) \f$.
/// Zero exactly at the Signorini states (1.22), for any r > 0.
inline double alart_curnier_normal(double lambda, double un, double g, double r) {
  return lambda - positive_part(lambda + r * (un - g));
}
/// \f$ \partial C / \partial\lambda = 1 - H \f$, \f$ H = d[\,]_+(\lambda + r(u_n - g)) \f$
/// (3.23, 3.25).
inline double d_alart_curnier_normal_d_lambda(double lambda, double un, double g, double r) {
  return 1.0 - d_positive_part(lambda + r * (un - g));
}
/// \f$ \partial C / \partial u_n = -r H \f$ (3.24, 3.26).
inline double d_alart_curnier_normal_d_un(double lambda, double un, double g, double r) {
  return -r * d_positive_part(lambda + r * (un - g));
}

/// Primal-dual active set, step (ii) after (3.29): node active (u_n = g imposed) iff
/// \f$ \lambda + \gamma (u_n - g) \ge 0 \f$; inactive nodes get \f$\lambda = 0\f$ (3.32).
/// Its residual is alart_curnier_normal with r = gamma (fixed point (3.20)).
inline bool pdas_is_active(double lambda, double un, double g, double gamma) {
  return lambda + gamma * (un - g) >= 0;
}

// --- Iterative projection (ch. 7) -------------------------------------------------------------

/// Iterative projection, step (ii) after (7.19): node active (u_n = g imposed, (7.21)) iff
/// \f$ (u_n - g) + c \lambda \ge 0 \f$; inactive nodes get the Robin condition (7.22).
inline bool projection_is_active(double lambda, double un, double g, double c) {
  return (un - g) + c * lambda >= 0;
}

/// Thesis (7.18) with gap:
/// \f$ P(\lambda, u_n) = (u_n - g) + [-(u_n - g) - c\lambda]_+ = \max(u_n - g, -c\lambda) \f$,
/// zero exactly at the Signorini states (fixed point (7.16)).
inline double projection_residual(double lambda, double un, double g, double c) {
  return (un - g) + positive_part(-(un - g) - c * lambda);
}
/// \f$ \partial P / \partial u_n \f$: 1 on the active branch \f$ P = u_n - g \f$, 0 on the
/// inactive branch \f$ P = -c\lambda \f$. At the kink \f$ (u_n - g) + c\lambda = 0 \f$ the active
/// branch is taken (projection_is_active), i.e. the derivative of \f$[y]_+\f$ at its argument
/// y = 0 is taken as 0 here: the inner argument is the negative of the active-set test.
inline double d_projection_residual_d_un(double lambda, double un, double g, double c) {
  return projection_is_active(lambda, un, g, c) ? 1.0 : 0.0;
}
/// \f$ \partial P / \partial\lambda \f$: 0 on the active branch, \f$ -c \f$ on the inactive one.
inline double d_projection_residual_d_lambda(double lambda, double un, double g, double c) {
  return projection_is_active(lambda, un, g, c) ? 0.0 : -c;
}

// --- Penalty and normal compliance ------------------------------------------------------------

/// Penalty (Remark 3.2: the augmented Lagrangian with lambda = 0, r = foundation stiffness):
/// contact force \f$ p = r [u_n - g]_+ \f$.
inline double penalty_force(double un, double g, double r) {
  return r * positive_part(un - g);
}
/// \f$ dp/du_n = r\,H(u_n - g) \f$, with \f$H(0) = 1\f$.
inline double d_penalty_force(double un, double g, double r) {
  return r * d_positive_part(un - g);
}

/// Normal compliance (1.24), \f$ -\sigma_n = p(u_n - g) = c_n [u_n - g]_+ \f$: the deformable
/// foundation starts to respond when the node reaches it (u_n = g, g the initial gap). For the
/// compliance with unilateral constraint (1.26) the rigid wall sits at g + layer thickness.
inline double normal_compliance(double un, double g, double cn) {
  return cn * positive_part(un - g);
}
/// \f$ dp/du_n = c_n H(u_n - g) \f$, with \f$H(0) = 1\f$.
inline double d_normal_compliance(double un, double g, double cn) {
  return cn * d_positive_part(un - g);
}

/// Truncated normal compliance of chapter 6: \f$ p = \min(c_n [u_n - g]_+, c_3) \f$, c_3 >= 0.
inline double truncated_normal_compliance(double un, double g, double cn, double c3) {
  const double p = normal_compliance(un, g, cn);
  return p < c3 ? p : c3;
}
/// \f$ dp/du_n \f$: \f$ c_n \f$ on \f$ 0 \le u_n - g \f$ below the cap, 0 on the plateau; the
/// cap's kink \f$ c_n (u_n - g) = c_3 \f$ belongs to the plateau.
inline double d_truncated_normal_compliance(double un, double g, double cn, double c3) {
  return normal_compliance(un, g, cn) < c3 ? d_normal_compliance(un, g, cn) : 0.0;
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
