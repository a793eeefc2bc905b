#pragma once
// The specific penalty of [62] (thesis (3.51), (8.32)): the normal force over a step from the
// penetration a at t_n to the penetration b at t_{n+1} is r p(a, b), with
//     p(a, b) = ([b]_+^2 - [a]_+^2) / (2 (b - a)),   p(a, a) = [a]_+ (the limit b -> a),
// the secant of the potential [.]_+^2 / 2. Its work over the step, r p(a, b) (b - a), is exactly
// the change of the penalty energy (r / 2)([b]_+^2 - [a]_+^2), so the midpoint rule conserves
// E + (r / 2) sum w [pen]_+^2 (3.53).
//
// Written by cases so that no branch divides by a small b - a: both positive gives the mean
// (a + b) / 2; one positive value s and one non-positive t give s^2 / (2 (s - t)), whose
// denominator is at least s. p is continuous, non-decreasing in b, and C1 except at a <= 0,
// b = 0 (where it starts from 0 with slope 0 for a < 0, 1/2 for a = 0).
namespace sig {

/// p(a, b) of (3.51): a, b the penetrations (u_n - gap) at t_n and t_{n+1}.
inline double specific_penalty(double a, double b) {
  if (a > 0 && b > 0) return 0.5 * (a + b);
  if (b > 0) return b * b / (2 * (b - a)); // a <= 0 < b
  if (a > 0) return a * a / (2 * (a - b)); // b <= 0 < a
  return 0.0;
}

/// dp/db, >= 0: the generalized Jacobian of the force at t_{n+1} (b <= 0 with a <= 0 gives 0).
inline double d_specific_penalty(double a, double b) {
  if (a > 0 && b > 0) return 0.5;
  if (b > 0) return b * (b - 2 * a) / (2 * (b - a) * (b - a));
  if (a > 0) return a * a / (2 * (a - b) * (a - b));
  return 0.0;
}

} // namespace sig
