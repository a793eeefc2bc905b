#include "contact/contact_kernel.hpp"

#include "contact/complementarity.hpp"

#include <algorithm>

namespace sig {

namespace {

/// The penetration the compliance sees: clipped at the wall, where the wall takes over.
double clipped(const ContactLaw& law, double q_n) {
  return law.has_wall() ? std::min(q_n, law.depth) : q_n;
}

} // namespace

double compliance_pressure(const ContactLaw& law, double q_n) {
  if (!law.has_compliance()) return 0.0;
  if (law.normal == NormalLaw::compliance_bilateral) return law.cn * q_n;
  if (law.secant) return law.cn * specific_penalty(law.previous, clipped(law, q_n));
  return truncated_normal_compliance(clipped(law, q_n), law.cn, law.c3);
}

double d_compliance_pressure(const ContactLaw& law, double q_n) {
  if (!law.has_compliance() || (law.has_wall() && q_n >= law.depth)) return 0.0;
  if (law.normal == NormalLaw::compliance_bilateral) return law.cn;
  if (law.secant) return law.cn * d_specific_penalty(law.previous, q_n);
  return d_truncated_normal_compliance(q_n, law.cn, law.c3);
}

double compliance_energy(const ContactLaw& law, double q_n) {
  if (!law.has_compliance() || law.in_velocity()) return 0.0;
  if (law.normal == NormalLaw::compliance_bilateral) return 0.5 * law.cn * q_n * q_n;
  const double q = positive_part(clipped(law, q_n));
  if (law.secant || law.cn * q <= law.c3) return 0.5 * law.cn * q * q;
  const double knee = law.c3 / law.cn; // the truncation: P = c3 beyond it
  return 0.5 * law.c3 * knee + law.c3 * (q - knee);
}

namespace {

double magnitude(double z) {
  return std::abs(z);
}
template <int n> double magnitude(const Eigen::Matrix<double, n, 1>& z) {
  return z.norm();
}

/// The node sits at the apex of the cone where a press would raise the bound: on an active wall
/// under Coulomb, or at a compliance's kink q_n = 0 (header: the stick side).
template <int d> bool at_apex(const ContactKernelIn<d>& k) {
  return k.bound == 0 && k.press_raises_bound;
}

/// The tangential rows of a 3D node with a held component (ContactLaw::held_tangent): the held
/// one sticks at its slip whatever its force, T_k = t_k + r_t (q_tk - held_k); the other, if
/// free, keeps the friction law on its line, the 2D kernel's projection on [-s, s] of z_j = t_j
/// + r_t q_tj (the disc cut by the held plane: no curvature term). The node sticks when the free
/// component does (or none is free), and slips along +-t_j otherwise.
void held_tangent_3d(const ContactLaw& law, const NodeVariablesIn<3>& x, double r_t,
                     const KernelBranchIn<3>* on, ContactKernelIn<3>& k) {
  using Col = KernelColumns<3>;
  k.stick = true;
  for (int c = 0; c < 2; ++c) {
    auto row = k.d_force.row(1 + c);
    const double z = x.t[c] + r_t * x.q_t[c];
    if (law.held_tangent[c]) {
      k.tangential[c] = z - r_t * law.held_slip[c];
      row[Col::q_t + c] = r_t;
      row[Col::t + c] = 1;
      continue;
    }
    const bool stick = on ? on->stick : (k.bound > 0 || at_apex(k)) && std::abs(z) <= k.bound;
    k.stick = stick;
    if (stick) {
      k.tangential[c] = z;
      row[Col::q_t + c] = r_t;
      row[Col::t + c] = 1;
    } else {
      const double sigma = on ? on->slip[c] : d_project_interval_ds(z, k.bound); // 0: z = s = 0
      k.slip[c] = sigma;
      k.tangential[c] = sigma * k.bound;
      row = sigma * k.d_bound;
    }
  }
}

/// The kernel at x, on its own branch or, given `on`, on that one.
template <int d>
ContactKernelIn<d> evaluate(const ContactLaw& law, const NodeVariablesIn<d>& x, double r_n,
                            double r_t, const KernelBranchIn<d>* on) {
  using Col = KernelColumns<d>;
  using TangentBlock = Eigen::Matrix<double, d - 1, d - 1>;
  ContactKernelIn<d> k;
  // Normal: compliance P plus the wall's augmented multiplier Lambda.
  k.compliance = compliance_pressure(law, x.q_n);
  k.compliance_slope = d_compliance_pressure(law, x.q_n);
  if (law.held_normal) { // bilateral: always on its wall, the reaction of either sign
    k.held = k.wall_active = true;
    k.wall = x.lambda + r_n * (x.q_n - law.depth);
  } else if (law.has_wall()) {
    const double augmented = x.lambda + r_n * (x.q_n - law.depth);
    k.wall_active = on ? on->wall : d_positive_part(augmented) > 0;
    k.wall = on ? (on->wall ? augmented : 0.0) : positive_part(augmented);
  }
  const double chi = k.wall_active ? 1.0 : 0.0;
  k.normal = k.compliance + k.wall;
  k.d_force(0, Col::q_n) = k.compliance_slope + chi * r_n;
  k.d_force(0, Col::lambda) = chi;
  k.complementarity[0] = x.lambda - k.wall;
  k.d_complementarity(0, Col::q_n) = -chi * r_n;
  k.d_complementarity(0, Col::lambda) = 1.0 - chi;

  // Tangential: the trial pressure projected on [-s, s] (the disc of radius s in 3D).
  switch (law.friction) {
  case FrictionLaw::none:
    break;
  case FrictionLaw::tresca:
    k.bound = law.threshold;
    break;
  case FrictionLaw::coulomb:
  case FrictionLaw::nonmonotone: // mu frozen for this convex solve (contact_law.hpp)
  case FrictionLaw::mu1:         // mu of the penetration (8.3)
  case FrictionLaw::mu2: {
    // A secant law's coefficient follows the deepest penetration of the step (contact_law.hpp).
    const bool deeper = !law.secant || x.q_n > law.previous;
    const double q_mu = deeper ? x.q_n : law.previous;
    const double mu = penetration_friction(law, q_mu);
    const double d_mu = deeper ? d_penetration_friction(law, q_mu) : 0.0;
    const bool whole = law.bound == FrictionBound::normal;
    const double pressure = whole ? k.normal : k.compliance;
    const double slope = whole ? k.d_force(0, Col::q_n) : k.compliance_slope;
    if (whole) {
      k.bound = mu * k.normal;
      k.bound_slope = mu;
      k.d_bound = mu * k.d_force.row(0);
      k.d_bound(Col::q_n) += d_mu * k.normal;
    } else { // the compliance pressure only: mu p(g), Tresca's, on the wall
      k.bound = mu * k.compliance;
      k.d_bound(Col::q_n) = mu * k.compliance_slope + d_mu * k.compliance;
    }
    // A press meets the coefficient of the deeper side (at q_n = 0 mu1's and mu2's, not the flat
    // side's 0): s = mu N rises to first order, or to second where mu and N both start from 0
    // (mu1 at rest on a compliance: s = mu0 cn q_n^2 / g).
    const PressedFriction pressed = penetration_friction_pressed(law, q_mu);
    const double d_mu_pressed = deeper ? pressed.slope : 0.0;
    k.press_raises_bound =
        pressed.mu * slope + d_mu_pressed * pressure > 0 || (d_mu_pressed > 0 && slope > 0);
    break;
  }
  }
  auto tangential_rows = k.d_force.template bottomRows<d - 1>();
  // T = t + r_t (q_t - q_0): the stick side's derivative.
  const auto stick_rows = [&] {
    tangential_rows.template middleCols<d - 1>(Col::q_t) = r_t * TangentBlock::Identity();
    tangential_rows.template middleCols<d - 1>(Col::t) = TangentBlock::Identity();
  };
  if (law.held_tangential()) { // stuck at the held slip, whatever the force
    if constexpr (d == 2) {
      k.stick = true;
      k.tangential = x.t + r_t * (x.q_t - law.held_slip[0]);
      stick_rows();
    } else {
      held_tangent_3d(law, x, r_t, on, k);
    }
  } else if (law.has_friction()) {
    const Tangent<d> z = x.t + r_t * x.q_t;
    const double size = magnitude(z);
    k.stick = on ? on->stick : (k.bound > 0 || at_apex(k)) && size <= k.bound;
    if (k.stick) {
      k.tangential = z;
      stick_rows();
    } else {
      if constexpr (d == 2)
        k.slip =
            on ? on->slip : static_cast<int>(d_project_interval_ds(z, k.bound)); // 0: z = s = 0
      else
        k.slip = size > 0 ? SlipDirection<d>(z / size) : on ? on->slip : SlipDirection<d>::Zero();
      k.tangential = k.slip * k.bound;
      tangential_rows = k.slip * k.d_bound;
      if constexpr (d > 2) { // the disc's edge turns with z: s (I - e e^T) / |z| dz
        if (size > 0) {
          const TangentBlock turn =
              k.bound / size * (TangentBlock::Identity() - k.slip * k.slip.transpose());
          tangential_rows.template middleCols<d - 1>(Col::q_t) += r_t * turn;
          tangential_rows.template middleCols<d - 1>(Col::t) += turn;
        }
      }
    }
  }
  if constexpr (d == 2)
    k.complementarity[1] = x.t - k.tangential;
  else
    k.complementarity.template tail<d - 1>() = x.t - k.tangential;
  k.d_complementarity.template bottomRows<d - 1>() = -tangential_rows;
  k.d_complementarity.template bottomRows<d - 1>().template middleCols<d - 1>(Col::t) +=
      TangentBlock::Identity();
  return k;
}

} // namespace

ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n,
                             double r_t) {
  return evaluate<2>(law, x, r_n, r_t, nullptr);
}

ContactKernel contact_kernel(const ContactLaw& law, const NodeVariables& x, double r_n, double r_t,
                             const KernelBranch& on) {
  return evaluate(law, x, r_n, r_t, &on);
}

ContactKernelIn<3> contact_kernel(const ContactLaw& law, const NodeVariablesIn<3>& x, double r_n,
                                  double r_t) {
  return evaluate<3>(law, x, r_n, r_t, nullptr);
}

ContactKernelIn<3> contact_kernel(const ContactLaw& law, const NodeVariablesIn<3>& x, double r_n,
                                  double r_t, const KernelBranchIn<3>& on) {
  return evaluate(law, x, r_n, r_t, &on);
}

} // namespace sig
