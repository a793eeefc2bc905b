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
// |t + r_t q_t| <= s and either s > 0 or the node sits at the apex of the Coulomb cone where a
// press would raise the bound (s = mu N = 0 on an active wall, chi = 1, or at a compliance's kink
// q_n = 0, N = cn [q_n]_+: a node that just touches, as every node in contact at rest does; the
// press meets the deeper side's coefficient, so mu1's s = mu0 cn q_n^2 / g rises too, though its
// ds/dq_n is 0 there), otherwise it slips with sigma = sign(t + r_t q_t) (0 when that is 0: a node
// with s = 0 that does not move). The apex is a kink of the projection like |z| = s, and belongs to
// the stick side as every kink belongs to contact: its slip element, T = 0, would hold nothing
// sideways, and a body held by friction alone would start from a step that drifts.
// In 3D (d = 3) the tangential quantities are vectors in the node's orthonormal tangent pair and
// the projection on [-s, s] becomes the one on the disc of radius s (the Coulomb cone's section):
// T = z on the stick side |z| <= s, T = s z / |z| beyond, whose derivative in z on the slip side
// is s (I - e e^T) / |z| with e = z / |z| (the curvature of the disc's edge, 0 in 2D where the
// "disc" is an interval). One template carries both dimensions: every line above holds with the
// scalars of 2D read as the 1-vectors they are.
#include "contact/contact_law.hpp"

#include <Eigen/Core>

#include <type_traits>

namespace sig {

/// A tangential quantity at a node of a d-dimensional body: a scalar along the one tangent in 2D,
/// its components in the node's orthonormal tangent pair in 3D.
template <int d>
using Tangent = std::conditional_t<d == 2, double, Eigen::Matrix<double, d - 1, 1>>;
/// The slip direction on the slip branch: sigma in {-1, 0, 1} in 2D, the unit vector z / |z| (0
/// where z = 0) in 3D.
template <int d>
using SlipDirection = std::conditional_t<d == 2, int, Eigen::Matrix<double, d - 1, 1>>;

template <int d> Tangent<d> zero_tangent() {
  if constexpr (d == 2)
    return 0.0;
  else
    return Tangent<d>::Zero();
}

/// The derivative columns of a d-dimensional kernel: q_n, the d - 1 slips, lambda, the d - 1
/// tangential multipliers (in 2D the order of enum Variable).
template <int d> struct KernelColumns {
  static constexpr int q_n = 0, q_t = 1, lambda = d, t = d + 1, count = 2 * d;
};

/// The variables of the kernel, in the order of its derivative columns.
template <int d> struct NodeVariablesIn {
  double q_n = 0;                     ///< penetration beyond the obstacle surface
  Tangent<d> q_t = zero_tangent<d>(); ///< slip
  double lambda = 0;                  ///< normal multiplier (pressure)
  Tangent<d> t = zero_tangent<d>();   ///< tangential multiplier (pressure)
};
using NodeVariables = NodeVariablesIn<2>;
enum Variable { kQn = 0, kQt = 1, kLambda = 2, kT = 3 };

template <int d> struct ContactKernelIn {
  using Row = Eigen::Matrix<double, 1, 2 * d>;
  using Rows = Eigen::Matrix<double, d, 2 * d>;
  double compliance = 0;                        ///< P
  double wall = 0;                              ///< Lambda
  double normal = 0;                            ///< N = P + Lambda
  double bound = 0;                             ///< s
  Tangent<d> tangential = zero_tangent<d>();    ///< T
  Eigen::Matrix<double, d, 1> complementarity = ///< (C_n, C_t)
      Eigen::Matrix<double, d, 1>::Zero();

  bool wall_active = false; ///< chi
  bool held = false;        ///< the normal component is held (ContactLaw::held_normal)
  bool stick = false;       ///< s > 0 and |t + r_t q_t| <= s
  /// sigma on the slip branch (header); 0 when sticking
  SlipDirection<d> slip = SlipDirection<d>(zero_tangent<d>());
  double compliance_slope = 0; ///< kappa = dP/dq_n
  /// ds/dN: mu where the bound is mu N (bound=normal), 0 where it does not follow N (tresca,
  /// bound=compliance); a linear step couples T to the wall's reaction through it
  double bound_slope = 0;
  /// Generalized derivative of s in (q_n, q_t, lambda, t)
  Row d_bound = Row::Zero();
  /// A press would raise s from here: the apex rule's test (header), one-sided at the kinks
  bool press_raises_bound = false;

  /// Generalized derivatives of (N, T) and of (C_n, C_t) in (q_n, q_t, lambda, t).
  Rows d_force = Rows::Zero();
  Rows d_complementarity = Rows::Zero();
};
using ContactKernel = ContactKernelIn<2>;

/// A branch of the kernel: the piece its positive part and its projection select.
template <int d> struct KernelBranchIn {
  bool wall = false;                                           ///< chi = 1
  bool stick = false;                                          ///< the projection's inside
  SlipDirection<d> slip = SlipDirection<d>(zero_tangent<d>()); ///< sigma on its outside
  bool operator==(const KernelBranchIn& o) const {
    if constexpr (d == 2)
      return wall == o.wall && stick == o.stick && slip == o.slip;
    else
      return wall == o.wall && stick == o.stick && (slip.array() == o.slip.array()).all();
  }
};
using KernelBranch = KernelBranchIn<2>;

/// The compliance pressure P(q_n) of a law (0 for signorini) and its slope, with the kinks
/// [q_n]_+ at 0 on the compliance side, the wall q_n = g and the truncation c3 on the flat side;
/// a secant law's P is its specific penalty from `previous` (contact_law.hpp).
double compliance_pressure(const ContactLaw& law, double q_n);
double d_compliance_pressure(const ContactLaw& law, double q_n);
/// The potential of the compliance, int_0^q_n P (clipped at the wall as P is): the energy the
/// foundation stores, per unit length (for a secant law, of the compliance it is the secant of;
/// 0 for signorini and for the laws in velocity, which store none).
double compliance_energy(const ContactLaw& law, double q_n);

/// The kernel at x (header comment), in 2D and in 3D.
ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n, double r_t);
ContactKernelIn<3> contact_kernel(const ContactLaw& law, const NodeVariablesIn<3>& x, double r_n,
                                  double r_t);

/// The branch the kernel k is on.
template <int d> KernelBranchIn<d> branch_of(const ContactKernelIn<d>& k) {
  return {k.wall_active, k.stick, k.slip};
}

/// The kernel's smooth piece `on` at x: the formulas above with chi, stick and sigma given
/// instead of read off x, i.e. Lambda = chi (lambda + r_n (q_n - g)) and T = t + r_t q_t
/// (stick) or sigma s (slip), even where x lies on another branch. It equals the kernel
/// wherever x lies on `on`; along a Newton step that changes branches it is the function the
/// step linearized (contact_newton.hpp measures its line search on it). The compliance P, a
/// function of q_n alone, is not held. In 3D the slip piece is s z / |z|, smooth wherever z != 0
/// (a held direction would not be the function the step linearized); `on`'s direction is taken
/// only at z = 0.
ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n, double r_t,
                             const KernelBranch& on);
ContactKernelIn<3> contact_kernel(const ContactLaw& law, const NodeVariablesIn<3>& x, double r_n,
                                  double r_t, const KernelBranchIn<3>& on);

} // namespace sig
