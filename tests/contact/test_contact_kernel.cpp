// The per-node contact kernel (contact/contact_kernel.hpp) for every normal law and friction law:
// its generalized derivatives against finite differences on both sides of every kink (offsets
// 1e-8 ... 1, augmentation parameters over decades), the derivative AT each kink against the
// one-sided difference into the side the kink belongs to, and the value identities: the
// Alart-Curnier functions vanish exactly on the states that satisfy the laws.
#include "contact/contact_kernel.hpp"
#include "contact/contact_status.hpp"
#include "core/error.hpp"
#include "kernel_laws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace sig {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const std::vector<double> kOffsets = {1e-8, 1e-6, 1e-4, 1e-2, 1.0};
const std::vector<double> kAugmentations = {1e-2, 1.0, 1e2, 1e4};

/// The kernel's four outputs (N, T, C_n, C_t) and the branch that must not change under a finite
/// difference step.
Eigen::Vector4d outputs(const ContactKernel& k) {
  return {k.normal, k.tangential, k.complementarity[0], k.complementarity[1]};
}
Eigen::Matrix4d derivatives(const ContactKernel& k) {
  Eigen::Matrix4d d;
  d << k.d_force, k.d_complementarity;
  return d;
}
bool same_branch(const ContactKernel& a, const ContactKernel& b) {
  return a.wall_active == b.wall_active && a.stick == b.stick && a.slip == b.slip &&
         a.compliance_slope == b.compliance_slope && (a.bound > 0) == (b.bound > 0);
}

NodeVariables with(NodeVariables x, int variable, double delta) {
  double* v[] = {&x.q_n, &x.q_t, &x.lambda, &x.t};
  *v[variable] += delta;
  return x;
}

double scale_of(const NodeVariables& x, double r) {
  return 1 + std::abs(x.q_n) * r + std::abs(x.q_t) * r + std::abs(x.lambda) + std::abs(x.t);
}

/// Central differences in each variable, with a step that stays on x's branch (the kernel is
/// piecewise affine, so the difference is exact there up to round-off).
void expect_derivatives(const ContactLaw& law, const NodeVariables& x, double r,
                        const std::string& where) {
  const ContactKernel k = contact_kernel(law, x, r, r);
  const Eigen::Matrix4d analytic = derivatives(k);
  for (int j = 0; j < 4; ++j) {
    double h = 1e-3 * (1 + std::abs(with(x, j, 0).q_n));
    ContactKernel plus, minus;
    for (; h > 1e-13; h /= 4) {
      plus = contact_kernel(law, with(x, j, h), r, r);
      minus = contact_kernel(law, with(x, j, -h), r, r);
      if (same_branch(plus, k) && same_branch(minus, k) &&
          same_coefficient_piece(law, x.q_n, with(x, j, h).q_n) &&
          same_coefficient_piece(law, x.q_n, with(x, j, -h).q_n))
        break;
    }
    ASSERT_GT(h, 1e-13) << where << ": no step stays on the branch in variable " << j;
    const Eigen::Vector4d fd = (outputs(plus) - outputs(minus)) / (2 * h);
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(analytic(i, j), fd[i],
                  1e-7 * (1 + std::abs(analytic(i, j))) + 16 * kEps * scale_of(x, r) / h)
          << where << ": output " << i << " variable " << j;
  }
}

/// At a kink: the derivative in `variable` is the one-sided difference into `side`.
void expect_kink_side(const ContactLaw& law, const NodeVariables& x, double r, int variable,
                      double side, const std::string& where) {
  const ContactKernel k = contact_kernel(law, x, r, r);
  for (double h : {1e-8, 1e-5}) {
    const Eigen::Vector4d one_sided =
        (outputs(contact_kernel(law, with(x, variable, side * h), r, r)) - outputs(k)) / (side * h);
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(derivatives(k)(i, variable), one_sided[i],
                  1e-6 * (1 + std::abs(derivatives(k)(i, variable))) +
                      16 * kEps * scale_of(x, r) / h)
          << where << ": output " << i << " h " << h;
  }
}

class EveryLaw : public ::testing::TestWithParam<KernelCase> {};

TEST_P(EveryLaw, DerivativesOnBothSidesOfEveryKink) {
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  for (double r : kAugmentations)
    for (double delta : kOffsets)
      for (double side : {-1.0, 1.0}) {
        const std::string where = "r " + std::to_string(r) + " offset " +
                                  std::to_string(side * delta) + " law " + describe(law);
        // The wall kink lambda + r (q_n - g) = 0, crossed along lambda.
        if (law.has_wall())
          for (double q_n : {-0.3, 0.1, 0.25, 0.9}) {
            const NodeVariables x{q_n, 0.02, -r * (q_n - law.depth) + side * delta, 0.1};
            expect_derivatives(law, x, r, "wall kink, " + where);
          }
        // The compliance's kinks: [q_n]+ at 0, the wall's clip at g, the truncation.
        if (law.has_compliance()) {
          expect_derivatives(law, {side * delta, -0.05, -1.0, 0.0}, r, "[q_n]+ kink, " + where);
          if (law.has_wall())
            expect_derivatives(law, {law.depth + side * delta, 0.05, -1.0 - 2 * r, 0.0}, r,
                               "clip at g, " + where);
          ContactLaw truncated = law;
          truncated.c3 = 1.5;
          expect_derivatives(truncated, {1.5 / law.cn + side * delta, 0.01, -1.0 - 2 * r, 0}, r,
                             "truncation, " + where);
        }
        // mu1 / mu2's kinks in the penetration, at 0 and g (sticking: the bound's slope in q_n
        // then shows in nothing but the statuses; slipping: in T).
        if (law.penetration_dependent())
          for (double q_n : {side * delta, law.depth + side * delta})
            for (double t : {0.0, 5.0})
              expect_derivatives(law, {q_n, 0.3, -1.0 - 2 * r, t}, r, "mu kink, " + where);
        // The friction kink |t + r q_t| = s on both bounds, crossed along t.
        if (law.has_friction())
          for (double sign : {-1.0, 1.0})
            for (double q_n : {0.1, 0.45}) {
              NodeVariables x{q_n, 0.03, 0.8, 0.0};
              const double s = contact_kernel(law, x, r, r).bound;
              x.t = sign * s - r * x.q_t + side * delta;
              expect_derivatives(law, x, r, "friction kink, " + where);
            }
      }
}

TEST_P(EveryLaw, DerivativeAtTheKinkIsTheOneOfItsSide) {
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  for (double r : kAugmentations) {
    const std::string where = "r " + std::to_string(r) + ", " + describe(law);
    if (law.has_wall()) // the kink belongs to the wall: increasing lambda stays active
      expect_kink_side(law, {0.1, 0.0, -r * (0.1 - law.depth), 0.0}, r, kLambda, 1.0,
                       "wall, " + where);
    if (law.has_compliance()) { // [q_n]+ at 0: to compliance
      expect_kink_side(law, {0.0, 0.0, -1.0, 0.0}, r, kQn, 1.0, "[q_n]+, " + where);
      if (law.has_wall()) // the clip at g: to the wall side, slope 0
        expect_kink_side(law, {law.depth, 0.0, -1.0 - 2 * r, 0.0}, r, kQn, 1.0, "clip, " + where);
    }
    if (law.has_friction()) { // |z| = s: to the inside (stick)
      NodeVariables x{0.45, 0.0, 0.8, 0.0};
      x.t = contact_kernel(law, x, r, r).bound;
      expect_kink_side(law, x, r, kT, -1.0, "friction, " + where);
    }
  }
}

/// Points on every branch of every law: off, on and beyond the wall; inside and beyond the slip
/// bound on either side (q_n away from the compliance's kinks, which a held branch keeps).
std::vector<NodeVariables> points_of_every_branch() {
  std::vector<NodeVariables> points;
  for (double q_n : {-0.3, 0.1, 0.25, 0.9})
    for (double lambda : {-2.0, 0.0, 0.7, 3.0})
      for (double q_t : {-0.5, 0.0, 0.02, 0.6})
        for (double t : {-1.5, 0.1, 2.0})
          points.push_back({q_n, q_t, lambda, t});
  return points;
}

TEST_P(EveryLaw, OnItsOwnBranchTheHeldKernelIsTheKernel) {
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction);
  for (double r : kAugmentations)
    for (const NodeVariables& x : points_of_every_branch()) {
      const ContactKernel k = contact_kernel(law, x, r, r);
      const ContactKernel held = contact_kernel(law, x, r, r, branch_of(k));
      EXPECT_EQ(outputs(held), outputs(k)) << describe(law) << " r " << r << " q_n " << x.q_n;
      EXPECT_EQ(derivatives(held), derivatives(k)) << describe(law) << " r " << r;
      EXPECT_EQ(branch_of(held), branch_of(k));
    }
}

TEST_P(EveryLaw, AHeldBranchIsItsPieceContinuedAcrossTheKinks) {
  // Held, the kernel is the branch's affine piece (in q_n, once the compliance is away from its
  // kinks) wherever x is: central differences over steps that cross the wall and friction kinks
  // equal the piece's derivatives, and the wall's multiplier goes negative where held.
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction);
  std::vector<KernelBranch> branches;
  for (bool wall : {false, true}) {
    branches.push_back({wall, true, 0});
    for (int slip : {-1, 1})
      branches.push_back({wall, false, slip});
  }
  const double r = 10, h = 0.05;
  for (const KernelBranch& on : branches)
    for (const NodeVariables& x : points_of_every_branch()) {
      const ContactKernel k = contact_kernel(law, x, r, r, on);
      EXPECT_EQ(k.wall_active, on.wall && law.has_wall());
      if (law.has_friction()) {
        EXPECT_EQ(branch_of(k).stick, on.stick);
      }
      for (int j = 0; j < 4; ++j) {
        const Eigen::Vector4d fd = (outputs(contact_kernel(law, with(x, j, h), r, r, on)) -
                                    outputs(contact_kernel(law, with(x, j, -h), r, r, on))) /
                                   (2 * h);
        for (int i = 0; i < 4; ++i)
          EXPECT_NEAR(derivatives(k)(i, j), fd[i], 1e-9 * (1 + r))
              << describe(law) << " wall " << on.wall << " stick " << on.stick << " slip "
              << on.slip << " output " << i << " variable " << j;
      }
    }
  if (!law.has_wall()) return;
  const NodeVariables tension{law.depth, 0.0, -1.0, 0.0};
  EXPECT_EQ(contact_kernel(law, tension, r, r).wall, 0.0);
  EXPECT_EQ(contact_kernel(law, tension, r, r, {true, false, 0}).wall, -1.0);
}

INSTANTIATE_TEST_SUITE_P(Laws, EveryLaw, ::testing::ValuesIn(every_kernel_case()));

// The bilateral test law: cn q_n on both sides of the surface, a spring in tension on its
// compliance branch (CN), no kink at q_n = 0.
TEST(ContactKernel, BilateralComplianceIsOneLinearSpring) {
  const ContactLaw law = law_of(NormalLaw::compliance_bilateral, FrictionLaw::none);
  for (double q_n : {-0.3, -1e-9, 0.0, 0.2}) {
    const ContactKernel k = contact_kernel(law, {q_n, 0.1, 0.0, 0.0}, 5.0, 5.0);
    EXPECT_EQ(k.normal, 7.5 * q_n);
    EXPECT_EQ(k.d_force(0, kQn), 7.5);
    EXPECT_EQ(normal_status(k), q_n == 0 ? NormalStatus::free : NormalStatus::compliance);
  }
}

// The laws in velocity are the compliance kernels of the velocity: the same forces, branches and
// derivatives at the same arguments, and the thesis's own status names.
TEST(ContactKernel, DampedLawsAreTheComplianceKernels) {
  for (FrictionLaw friction : {FrictionLaw::none, FrictionLaw::coulomb})
    for (auto [velocity, displacement] :
         {std::pair{NormalLaw::damped, NormalLaw::compliance},
          std::pair{NormalLaw::damped_unilateral, NormalLaw::compliance_unilateral}}) {
      const ContactLaw v = law_of(velocity, friction), d = law_of(displacement, friction);
      EXPECT_TRUE(v.in_velocity());
      EXPECT_FALSE(d.in_velocity());
      EXPECT_EQ(v.has_wall(), d.has_wall());
      for (double q_n : {-0.1, 0.0, 0.2, 0.4, 0.5})
        for (double q_t : {-0.3, 0.0, 0.1}) {
          const ContactKernel a = contact_kernel(v, {q_n, q_t, 1.5, 0.2}, 10, 10);
          const ContactKernel b = contact_kernel(d, {q_n, q_t, 1.5, 0.2}, 10, 10);
          EXPECT_EQ(a.normal, b.normal);
          EXPECT_EQ(a.tangential, b.tangential);
          EXPECT_EQ(a.d_force, b.d_force);
          EXPECT_EQ(a.d_complementarity, b.d_complementarity);
          EXPECT_EQ(normal_status(a), normal_status(b));
        }
    }
  const ContactLaw damped = law_of(NormalLaw::damped_unilateral, FrictionLaw::none);
  EXPECT_EQ(label(NormalStatus::compliance, damped), "RNI");
  EXPECT_EQ(label(NormalStatus::unilateral, damped), "CUV");
  EXPECT_EQ(label(NormalStatus::free, damped), "free");
  EXPECT_EQ(label(NormalStatus::compliance, law_of(NormalLaw::compliance, FrictionLaw::none)),
            "CN");
}

TEST(ContactKernel, ZerosAreTheSignoriniCoulombStates) {
  const ContactLaw law = law_of(NormalLaw::signorini, FrictionLaw::coulomb);
  const double g = law.depth;
  for (double r : kAugmentations) {
    // Contact and stick: q_n = g, lambda > 0, q_t = 0, |t| < mu lambda.
    EXPECT_EQ(contact_kernel(law, {g, 0.0, 2.0, 0.3}, r, r).complementarity.norm(), 0.0);
    // Contact and slip: t = mu lambda sign(q_t).
    EXPECT_NEAR(contact_kernel(law, {g, -0.2, 2.0, -0.6}, r, r).complementarity.norm(), 0.0, 1e-15);
    // Separated: lambda = t = 0, q_n < g, any slip.
    EXPECT_EQ(contact_kernel(law, {g - 0.1, 5.0, 0.0, 0.0}, r, r).complementarity.norm(), 0.0);
    // Violations: penetration, tension, friction beyond the cone, slip against the force.
    EXPECT_GT(std::abs(contact_kernel(law, {g + 0.1, 0.0, 0.0, 0.0}, r, r).complementarity[0]), 0);
    EXPECT_GT(std::abs(contact_kernel(law, {g, 0.0, -1.0, 0.0}, r, r).complementarity[0]), 0);
    EXPECT_GT(std::abs(contact_kernel(law, {g, 0.0, 2.0, 0.7}, r, r).complementarity[1]), 0);
    EXPECT_GT(std::abs(contact_kernel(law, {g, 0.2, 2.0, -0.6}, r, r).complementarity[1]), 0);
  }
}

TEST(ContactKernel, ComplianceForcesAndWall) {
  ContactLaw law = law_of(NormalLaw::compliance_unilateral, FrictionLaw::none);
  // Between the surface and the wall: the compliance alone, CN.
  const ContactKernel between = contact_kernel(law, {0.2, 0.0, 0.0, 0.0}, 10, 10);
  EXPECT_DOUBLE_EQ(between.normal, law.cn * 0.2);
  EXPECT_EQ(normal_status(between), NormalStatus::compliance);
  // On the wall: p(g) plus the wall's multiplier, CU.
  const ContactKernel wall = contact_kernel(law, {0.4, 0.0, 3.0, 0.0}, 10, 10);
  EXPECT_DOUBLE_EQ(wall.normal, law.cn * 0.4 + 3.0);
  EXPECT_EQ(normal_status(wall), NormalStatus::unilateral);
  // Off the obstacle: free.
  EXPECT_EQ(normal_status(contact_kernel(law, {-0.1, 0.0, 0.0, 0.0}, 10, 10)), NormalStatus::free);
  // Pure compliance has no wall: deep penetration is compliance, truncated at c3.
  law.normal = NormalLaw::compliance;
  law.c3 = 9.0;
  const ContactKernel deep = contact_kernel(law, {5.0, 0.0, 1.0, 0.0}, 10, 10);
  EXPECT_DOUBLE_EQ(deep.normal, 9.0);
  EXPECT_EQ(deep.complementarity[0], 1.0); // lambda must vanish without a wall
  EXPECT_EQ(normal_status(deep), NormalStatus::compliance);
}

TEST(ContactKernel, FrictionStatuses) {
  const ContactLaw coulomb = law_of(NormalLaw::signorini, FrictionLaw::coulomb);
  const double g = coulomb.depth;
  EXPECT_EQ(friction_status(coulomb, contact_kernel(coulomb, {g, 0.0, 2.0, 0.3}, 1, 1)),
            FrictionStatus::stick);
  EXPECT_EQ(friction_status(coulomb, contact_kernel(coulomb, {g, 0.5, 2.0, 0.6}, 1, 1)),
            FrictionStatus::slip_forward);
  EXPECT_EQ(friction_status(coulomb, contact_kernel(coulomb, {g, -0.5, 2.0, -0.6}, 1, 1)),
            FrictionStatus::slip_backward);
  // Coulomb off the obstacle: no friction acts.
  EXPECT_EQ(friction_status(coulomb, contact_kernel(coulomb, {-1.0, 0.5, 0.0, 0.0}, 1, 1)),
            FrictionStatus::none);
  // Tresca bounds the slip on every node, in contact or not.
  const ContactLaw tresca = law_of(NormalLaw::signorini, FrictionLaw::tresca);
  EXPECT_EQ(friction_status(tresca, contact_kernel(tresca, {-1.0, 0.0, 0.0, 1.0}, 1, 1)),
            FrictionStatus::stick);
  EXPECT_EQ(friction_status(tresca, contact_kernel(tresca, {-1.0, 1.0, 0.0, 2.0}, 1, 1)),
            FrictionStatus::slip_forward);
  // A zero threshold never sticks: it slips along any slip, and at none it is not S=.
  ContactLaw loose = tresca;
  loose.threshold = 0;
  EXPECT_EQ(friction_status(loose, contact_kernel(loose, {-1.0, -1.0, 0.0, 0.0}, 1, 1)),
            FrictionStatus::slip_backward);
  EXPECT_EQ(friction_status(loose, contact_kernel(loose, {-1.0, 0.0, 0.0, 0.0}, 1, 1)),
            FrictionStatus::none);
  // Frictionless: no status.
  const ContactLaw none = law_of(NormalLaw::signorini, FrictionLaw::none);
  EXPECT_EQ(friction_status(none, contact_kernel(none, {g, 0.5, 2.0, 0.0}, 1, 1)),
            FrictionStatus::none);
  for (long code = 0; code <= 3; ++code)
    EXPECT_EQ(static_cast<long>(friction_status_of_code(code)), code);
  EXPECT_EQ(label(FrictionStatus::slip_backward), "S-");
  EXPECT_EQ(label(NormalStatus::compliance), "CN");
  EXPECT_EQ(normal_status_of_code(3), NormalStatus::held);
  EXPECT_THROW(normal_status_of_code(4), Error);
}

TEST(ContactKernel, TheConeApexOnTheWallSticks) {
  // A node just touching at rest: on the wall (lambda + r (q_n - g) = 0), the Coulomb bound
  // s = mu N = 0 and z = 0. Its kink belongs to stick: the slip is imposed, q_t = 0, and a
  // growing normal force (lambda up) keeps it inside the cone, the side its derivative is.
  const ContactLaw coulomb = law_of(NormalLaw::signorini, FrictionLaw::coulomb);
  for (double r : kAugmentations) {
    const NodeVariables apex{coulomb.depth, 0.0, 0.0, 0.0};
    const ContactKernel k = contact_kernel(coulomb, apex, r, r);
    EXPECT_TRUE(k.wall_active);
    EXPECT_EQ(k.bound, 0.0);
    EXPECT_TRUE(k.stick) << "r " << r;
    EXPECT_EQ(k.d_force(1, kQt), r);
    expect_kink_side(coulomb, apex, r, kLambda, 1.0, "apex, r " + std::to_string(r));
  }
  // Off the wall, or under a bound that a press does not raise (Tresca's zero threshold), the
  // apex slips with sigma = 0: T = 0, nothing held.
  EXPECT_FALSE(contact_kernel(coulomb, {coulomb.depth - 0.1, 0.0, 0.0, 0.0}, 1, 1).stick);
  ContactLaw loose = law_of(NormalLaw::signorini, FrictionLaw::tresca);
  loose.threshold = 0;
  EXPECT_FALSE(contact_kernel(loose, {loose.depth, 0.0, 0.0, 0.0}, 1, 1).stick);
  // A compliance at its kink q_n = 0 (the contact side, slope cn): Coulomb's bound mu cn [q_n]_+
  // rises with a press, so its apex sticks as the wall's does (a body at rest on a compliant
  // foundation held by friction alone starts from a step that holds it); apart (q_n < 0) the
  // node slips with nothing to hold.
  const ContactLaw compliance = law_of(NormalLaw::compliance, FrictionLaw::coulomb);
  for (double r : kAugmentations) {
    const NodeVariables apex{0.0, 0.0, 0.0, 0.0};
    EXPECT_TRUE(contact_kernel(compliance, apex, r, r).stick) << "r " << r;
    expect_kink_side(compliance, apex, r, kQn, 1.0, "compliance apex, r " + std::to_string(r));
  }
  EXPECT_FALSE(contact_kernel(compliance, {-0.1, 0.0, 0.0, 0.0}, 1, 1).stick);
  // mu1 and mu2 (8.3) at rest on a compliance: their coefficient at q_n = 0 is the flat side's 0,
  // so s and ds/dq_n are both 0 there, but a press meets the deeper side's (mu1 rising from 0,
  // s = mu0 cn q_n^2 / g; mu2 from 2 mu0): s rises, and the apex sticks.
  for (const FrictionLaw f : {FrictionLaw::mu1, FrictionLaw::mu2}) {
    const ContactLaw law = law_of(NormalLaw::compliance_unilateral, f);
    for (double r : kAugmentations) {
      const NodeVariables apex{0.0, 0.0, 0.0, 0.0};
      const ContactKernel k = contact_kernel(law, apex, r, r);
      EXPECT_EQ(k.bound, 0.0);
      EXPECT_EQ(k.d_bound[kQn], 0.0);
      EXPECT_TRUE(k.stick) << to_string(f) << ", r " << r;
      expect_kink_side(law, apex, r, kQn, 1.0, to_string(f) + " apex, r " + std::to_string(r));
    }
    EXPECT_FALSE(contact_kernel(law, {-0.1, 0.0, 0.0, 0.0}, 1, 1).stick);
  }
}

TEST(ContactKernel, HeldComponentsAreABilateralWallAndAStick) {
  // A roller on a contact node (ContactLaw::held_normal / held_tangential): the normal is on its
  // wall whatever the sign of the reaction, the tangential component sticks at its held slip
  // whatever the force; each kernel is smooth (one branch) and its derivative the exact one.
  ContactLaw held = law_of(NormalLaw::signorini, FrictionLaw::none);
  held.held_normal = held.held_tangent[0] = true;
  held.depth = -0.2; // held away from the surface
  held.held_slip[0] = 0.05;
  for (double r : kAugmentations)
    for (const NodeVariables& x : points_of_every_branch()) {
      const ContactKernel k = contact_kernel(held, x, r, r);
      EXPECT_TRUE(k.wall_active && k.held && k.stick);
      EXPECT_DOUBLE_EQ(k.normal, x.lambda + r * (x.q_n - held.depth));
      EXPECT_DOUBLE_EQ(k.tangential, x.t + r * (x.q_t - held.held_slip[0]));
      EXPECT_EQ(normal_status(k), NormalStatus::held);
      EXPECT_EQ(friction_status(held, k), FrictionStatus::stick);
      expect_derivatives(held, x, r, "held, r " + std::to_string(r));
    }
  // Its zeros are the held values, with any reaction.
  const ContactKernel at = contact_kernel(held, {held.depth, held.held_slip[0], -3.0, 7.0}, 1, 1);
  EXPECT_EQ(at.complementarity, Eigen::Vector2d::Zero());
  EXPECT_FALSE(law_problem(held).has_value());
  held.friction = FrictionLaw::coulomb; // out of contact: no friction law
  EXPECT_TRUE(law_problem(held).has_value());
}

TEST(ContactKernel, ComplianceBoundIsTrescaOnTheWall) {
  // bound=compliance: s = mu p(min(q_n, g)). On the wall the reaction does not enter it, so the
  // node is a Tresca node of threshold mu p(g) (l.5767), whatever the wall's multiplier.
  const ContactLaw law =
      law_of(NormalLaw::compliance_unilateral, FrictionLaw::coulomb, FrictionBound::compliance);
  ContactLaw tresca = law;
  tresca.friction = FrictionLaw::tresca;
  tresca.threshold = law.mu * law.cn * law.depth;
  for (double lambda : {0.5, 3.0, 30.0})
    for (double q_t : {-0.2, 0.0, 1e-3, 0.2}) {
      const NodeVariables x{law.depth, q_t, lambda, 0.1};
      const ContactKernel k = contact_kernel(law, x, 10, 10);
      const ContactKernel t = contact_kernel(tresca, x, 10, 10);
      ASSERT_TRUE(k.wall_active);
      EXPECT_DOUBLE_EQ(k.bound, tresca.threshold);
      EXPECT_DOUBLE_EQ(k.tangential, t.tangential);
      EXPECT_EQ(k.bound_slope, 0.0); // a linear step couples nothing to the reaction
      EXPECT_EQ(k.d_force, t.d_force);
      EXPECT_EQ(friction_status(law, k), friction_status(tresca, t));
    }
  // Between the surface and the wall it follows the compliance: mu cn q_n, as Coulomb there.
  ContactLaw coulomb = law;
  coulomb.bound = FrictionBound::normal;
  const NodeVariables between{0.2, 0.05, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(contact_kernel(law, between, 10, 10).bound, law.mu * law.cn * 0.2);
  EXPECT_DOUBLE_EQ(contact_kernel(law, between, 10, 10).tangential,
                   contact_kernel(coulomb, between, 10, 10).tangential);
  // On the wall bound=normal adds the reaction: a larger bound.
  EXPECT_GT(contact_kernel(coulomb, {law.depth, 0.0, 3.0, 0.0}, 10, 10).bound,
            contact_kernel(law, {law.depth, 0.0, 3.0, 0.0}, 10, 10).bound);
}

// (8.3): mu1 rises from 0 to mu0 over the asperities' depth g, mu2 falls from 2 mu0 to mu0; both
// are mu0 once the asperities are crushed and 0 off the obstacle, and mu2 >= mu1 in between.
TEST(ContactKernel, PenetrationDependentCoefficients) {
  ContactLaw mu1 = law_of(NormalLaw::compliance_unilateral, FrictionLaw::mu1);
  ContactLaw mu2 = law_of(NormalLaw::compliance_unilateral, FrictionLaw::mu2);
  const double g = mu1.depth, mu0 = mu1.mu;
  for (double q : {-0.1, 0.0})
    EXPECT_EQ(penetration_friction(mu1, q) + penetration_friction(mu2, q), 0.0);
  EXPECT_DOUBLE_EQ(penetration_friction(mu1, g / 4), mu0 / 4);
  EXPECT_DOUBLE_EQ(penetration_friction(mu2, g / 4), 1.75 * mu0);
  EXPECT_DOUBLE_EQ(penetration_friction(mu2, 1e-12), 2 * mu0 * (1 - 0.5e-12 / g));
  for (double q : {g, 2 * g}) {
    EXPECT_EQ(penetration_friction(mu1, q), mu0);
    EXPECT_EQ(penetration_friction(mu2, q), mu0);
    EXPECT_EQ(d_penetration_friction(mu1, q), 0.0); // the kinks belong to the flat sides
  }
  EXPECT_EQ(d_penetration_friction(mu2, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(d_penetration_friction(mu1, g / 2), mu0 / g);
  EXPECT_DOUBLE_EQ(d_penetration_friction(mu2, g / 2), -mu0 / g);
  for (int i = 1; i < 100; ++i) // mu2 >= mu1 on (0, g): it dissipates more
    EXPECT_GE(penetration_friction(mu2, i * g / 100), penetration_friction(mu1, i * g / 100));
  // Coulomb keeps its coefficient; the threshold mu2 p stays continuous at 0 since p(0) = 0.
  EXPECT_EQ(penetration_friction(law_of(NormalLaw::signorini, FrictionLaw::coulomb), 1.0), 0.3);
  const ContactKernel at_zero = contact_kernel(mu2, {1e-14, 0.0, 0.0, 0.0}, 10, 10);
  EXPECT_LT(at_zero.bound, 1e-12);
  // law_problem: the asperities need a depth.
  mu1.depth = 0;
  ASSERT_TRUE(law_problem(mu1).has_value());
  EXPECT_EQ(law_problem(mu1)->field, "g");
  EXPECT_EQ(friction_law_named("mu2"), FrictionLaw::mu2);
  EXPECT_EQ(friction_law_of_id(5), FrictionLaw::mu2);
  (void)mu2;
}

// The specific penalty's secant (contact_law.hpp): its compliance is p_spe(previous, q_n), and
// mu1 / mu2 follow the step's deepest penetration, so that the bound stays continuous where the
// secant force of a leaving node does not vanish at q_n = 0; derivatives against central
// differences on the secant's branches.
TEST(ContactKernel, SecantLawsAndTheDeepestPenetrationOfTheStep) {
  for (FrictionLaw friction : {FrictionLaw::coulomb, FrictionLaw::mu1, FrictionLaw::mu2})
    for (NormalLaw normal : {NormalLaw::compliance, NormalLaw::compliance_unilateral}) {
      ContactLaw law = law_of(normal, friction);
      law.depth = 0.4;
      law.secant = true;
      for (double previous : {-0.2, 0.05, 0.3}) {
        law.previous = previous;
        // The work identity of the secant: P (q - previous) = cn ([q]_+^2 - [previous]_+^2) / 2.
        for (double q : {-0.1, 0.02, 0.2, 0.35})
          if (q != previous) {
            const double P = compliance_pressure(law, q);
            EXPECT_NEAR(P * (q - previous),
                        compliance_energy(law, q) - compliance_energy(law, previous), 1e-12);
          }
        // The secant is smooth, not piecewise affine, on its pieces: central differences of
        // step 1e-6 away from the kinks at 0, previous and g.
        for (double q : {-0.15, 0.01, 0.12, 0.28})
          for (double t : {0.0, 0.6}) {
            const NodeVariables x{q, 0.05, -1.0, t};
            const ContactKernel k = contact_kernel(law, x, 10, 10);
            for (int j = 0; j < 4; ++j) {
              const double h = 1e-6;
              const Eigen::Vector4d fd = (outputs(contact_kernel(law, with(x, j, h), 10, 10)) -
                                          outputs(contact_kernel(law, with(x, j, -h), 10, 10))) /
                                         (2 * h);
              for (int i = 0; i < 4; ++i)
                EXPECT_NEAR(derivatives(k)(i, j), fd[i], 1e-6 * (1 + std::abs(fd[i])))
                    << describe(law) << " previous " << previous << " q " << q << " output " << i
                    << " variable " << j;
            }
          }
      }
      // The bound across q_n = 0 with a penetration at the start: continuous for every law.
      law.previous = 0.05;
      const double below = contact_kernel(law, {-1e-9, 0.3, -1.0, 0.0}, 10, 10).bound;
      const double above = contact_kernel(law, {1e-9, 0.3, -1.0, 0.0}, 10, 10).bound;
      EXPECT_NEAR(below, above, 1e-7) << describe(law);
      EXPECT_GT(below, 0.0) << describe(law);
      if (law.penetration_dependent()) {
        // Shallower than at the start: the coefficient of the start's penetration.
        EXPECT_DOUBLE_EQ(contact_kernel(law, {0.01, 0.3, -1.0, 0.0}, 10, 10).bound,
                         penetration_friction(law, 0.05) *
                             contact_kernel(law, {0.01, 0.3, -1.0, 0.0}, 10, 10).normal);
      }
    }
}

TEST(ContactKernel, NonmonotoneWithEqualCoefficientsIsCoulomb) {
  // a = b: mu(r) = a for every slip, whatever alpha; the kernel is Coulomb's with mu = a.
  for (FrictionBound bound : {FrictionBound::normal, FrictionBound::compliance}) {
    ContactLaw nonmonotone =
        law_of(NormalLaw::compliance_unilateral, FrictionLaw::nonmonotone, bound);
    nonmonotone.a = nonmonotone.b = 0.7;
    ContactLaw coulomb = law_of(NormalLaw::compliance_unilateral, FrictionLaw::coulomb, bound);
    coulomb.mu = 0.7;
    for (double r : {0.0, 1e-3, 0.5, 50.0}) {
      EXPECT_EQ(friction_coefficient(nonmonotone, r), 0.7);
      EXPECT_EQ(d_friction_coefficient(nonmonotone, r), 0.0);
    }
    nonmonotone.mu = friction_coefficient(nonmonotone, 0.3);
    for (const NodeVariables& x :
         {NodeVariables{0.1, 0.02, 0.0, 0.3}, NodeVariables{0.4, -0.1, 2.0, -0.5},
          NodeVariables{-0.2, 0.1, 0.0, 0.0}}) {
      const ContactKernel n = contact_kernel(nonmonotone, x, 10, 10);
      const ContactKernel c = contact_kernel(coulomb, x, 10, 10);
      EXPECT_EQ(outputs(n), outputs(c));
      EXPECT_EQ(derivatives(n), derivatives(c));
      EXPECT_EQ(friction_status(nonmonotone, n), friction_status(coulomb, c));
    }
  }
}

TEST(ContactKernel, NonmonotoneCoefficientAndItsSlope) {
  // (1.39): mu(0) = a, mu -> b, and the slope against central differences.
  ContactLaw law = law_of(NormalLaw::compliance, FrictionLaw::nonmonotone);
  EXPECT_DOUBLE_EQ(friction_coefficient(law, 0.0), law.a);
  EXPECT_NEAR(friction_coefficient(law, 1e3), law.b, 1e-15);
  for (double r : {0.0, 1e-3, 0.1, 1.0, 5.0}) {
    const double h = 1e-6;
    const double fd =
        (friction_coefficient(law, r + h) - friction_coefficient(law, std::max(r - h, 0.0))) /
        (r + h - std::max(r - h, 0.0));
    EXPECT_NEAR(d_friction_coefficient(law, r), fd, 1e-6 * (1 + std::abs(fd))) << r;
    EXPECT_LE(friction_coefficient(law, r), law.a);
    EXPECT_GE(friction_coefficient(law, r), law.b);
  }
  // Other laws: coulomb's mu, 0 without a coefficient.
  EXPECT_EQ(friction_coefficient(law_of(NormalLaw::compliance, FrictionLaw::coulomb), 2.0), 0.3);
  EXPECT_EQ(friction_coefficient(law_of(NormalLaw::compliance, FrictionLaw::tresca), 2.0), 0.0);
}

} // namespace
} // namespace sig

namespace sig {
namespace {

// The compliance's energy is the integral of its pressure: its central difference is P, on both
// sides of the obstacle surface and of the truncation, up to the wall.
TEST(ContactKernel, ComplianceEnergyIntegratesThePressure) {
  ContactLaw truncated = law_of(NormalLaw::compliance, FrictionLaw::none);
  truncated.c3 = 1.5; // the knee at q_n = 0.2
  const ContactLaw unilateral = law_of(NormalLaw::compliance_unilateral, FrictionLaw::none);
  const ContactLaw bilateral = law_of(NormalLaw::compliance_bilateral, FrictionLaw::none);
  for (const ContactLaw& law : {truncated, unilateral, bilateral})
    for (double q : {-0.3, -0.01, 0.05, 0.19, 0.21, 0.35, 0.39}) {
      const double h = 1e-6;
      const double slope =
          (compliance_energy(law, q + h) - compliance_energy(law, q - h)) / (2 * h);
      EXPECT_NEAR(slope, compliance_pressure(law, q), 1e-8) << describe(law) << " q_n " << q;
    }
  EXPECT_EQ(compliance_energy(law_of(NormalLaw::signorini, FrictionLaw::none), 0.3), 0.0);
  EXPECT_EQ(compliance_energy(truncated, -0.1), 0.0);
}

} // namespace
} // namespace sig
