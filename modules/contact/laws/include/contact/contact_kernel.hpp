#pragma once
// The per-node contact kernel (ALGORITHMS.md 0.3): Alart-Curnier's augmented Lagrangian
// (3.17)-(3.19) for the wall and the friction, with the compliance of the normal law added as a
// penalty, as the thesis solves it (l.7612-7618, 9774-9781, 12422-12428). Everything is a
// pressure (force per unit length of Gamma3); the nodal weight makes forces of them.
//
// At a node with penetration q_n, slip q_t (contact_law.hpp), normal multiplier lambda and
// tangential multiplier t, and augmentation parameters r_n, r_t > 0:
//   P = p(q_n)                                  compliance, clipped at the wall: p(min(q_n, g))
//   Lambda = [lambda + r_n (q_n - g)]_+         wall (laws with a wall; else 0)
//   N = P + Lambda                              normal pressure on the body
//   s = threshold | mu N | mu P | 0             slip bound (tresca | coulomb or nonmonotone
//                                               with bound=normal | bound=compliance | none)
//   T = proj_[-s, s](t + r_t q_t)               tangential pressure (0 without friction)
//   C_n = lambda - Lambda,  C_t = t - T         the Alart-Curnier functions, -r times the rows
//                                               R of (3.19): zero exactly where the laws hold
// The multiplier of a law without a wall, and the tangential one without friction, are then
// forced to 0 by C. Penalty (Remark 3.2) is this kernel with lambda = t = 0 and r the foundation
// stiffness: N and T are then the penalty forces.
//
// Branches (the generalized derivative is the one of the branch, kinks as complementarity.hpp):
// the wall is active (chi = 1) iff lambda + r_n (q_n - g) >= 0; the node sticks iff
// |t + r_t q_t| <= s and either s > 0 or the node sits at the apex of the Coulomb cone on an
// active wall (s = mu N = 0, chi = 1: a node that just touches, as every node in contact at rest
// does), otherwise it slips with sigma = sign(t + r_t q_t) (0 when that is 0, a node with s = 0
// that does not move). The apex is a kink of the projection like |z| = s, and belongs to the
// stick side as every kink belongs to contact: its slip element, T = 0, would hold nothing
// sideways, and a body held by friction alone would start from a step that drifts.
#include "contact/contact_law.hpp"

#include <Eigen/Core>

namespace sig {

/// The variables of the kernel, in the order of its derivative columns.
struct NodeVariables {
  double q_n = 0;    ///< penetration beyond the obstacle surface
  double q_t = 0;    ///< slip
  double lambda = 0; ///< normal multiplier (pressure)
  double t = 0;      ///< tangential multiplier (pressure)
};
enum Variable { kQn = 0, kQt = 1, kLambda = 2, kT = 3 };

struct ContactKernel {
  double compliance = 0;                                     ///< P
  double wall = 0;                                           ///< Lambda
  double normal = 0;                                         ///< N = P + Lambda
  double bound = 0;                                          ///< s
  double tangential = 0;                                     ///< T
  Eigen::Vector2d complementarity = Eigen::Vector2d::Zero(); ///< (C_n, C_t)

  bool wall_active = false;    ///< chi
  bool held = false;           ///< the normal component is held (ContactLaw::held_normal)
  bool stick = false;          ///< s > 0 and |t + r_t q_t| <= s
  int slip = 0;                ///< sigma on the slip branch (-1, 0, 1); 0 when sticking
  double compliance_slope = 0; ///< kappa = dP/dq_n
  /// ds/dN: mu where the bound is mu N (bound=normal), 0 where it does not follow N (tresca,
  /// bound=compliance); a linear step couples T to the wall's reaction through it
  double bound_slope = 0;
  /// Generalized derivative of s in (q_n, q_t, lambda, t)
  Eigen::Matrix<double, 1, 4> d_bound = Eigen::Matrix<double, 1, 4>::Zero();

  /// Generalized derivatives of (N, T) and of (C_n, C_t) in (q_n, q_t, lambda, t).
  Eigen::Matrix<double, 2, 4> d_force = Eigen::Matrix<double, 2, 4>::Zero();
  Eigen::Matrix<double, 2, 4> d_complementarity = Eigen::Matrix<double, 2, 4>::Zero();
};

/// A branch of the kernel: the piece its positive part and its projection select.
struct KernelBranch {
  bool wall = false;  ///< chi = 1
  bool stick = false; ///< the projection's inside
  int slip = 0;       ///< sigma on its outside
  bool operator==(const KernelBranch&) const = default;
};

/// The compliance pressure P(q_n) of a law (0 for signorini) and its slope, with the kinks
/// [q_n]_+ at 0 on the compliance side, the wall q_n = g and the truncation c3 on the flat side;
/// a secant law's P is its specific penalty from `previous` (contact_law.hpp).
double compliance_pressure(const ContactLaw& law, double q_n);
double d_compliance_pressure(const ContactLaw& law, double q_n);
/// The potential of the compliance, int_0^q_n P (clipped at the wall as P is): the energy the
/// foundation stores, per unit length (for a secant law, of the compliance it is the secant of;
/// 0 for signorini and for the laws in velocity, which store none).
double compliance_energy(const ContactLaw& law, double q_n);

/// The kernel at x (header comment).
ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n, double r_t);

/// The branch the kernel k is on.
inline KernelBranch branch_of(const ContactKernel& k) {
  return {k.wall_active, k.stick, k.slip};
}

/// The kernel's smooth piece `on` at x: the formulas above with chi, stick and sigma given
/// instead of read off x, i.e. Lambda = chi (lambda + r_n (q_n - g)) and T = t + r_t q_t
/// (stick) or sigma s (slip), even where x lies on another branch. It equals the kernel
/// wherever x lies on `on`; along a Newton step that changes branches it is the function the
/// step linearized (contact_newton.hpp measures its line search on it). The compliance P, a
/// function of q_n alone, is not held.
ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n, double r_t,
                             const KernelBranch& on);

} // namespace sig
