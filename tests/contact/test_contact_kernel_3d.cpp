// The contact kernel of a 3D body (contact/contact_kernel.hpp, d = 3): the tangential force
// projected on the disc of radius s in the tangent plane (the Coulomb cone's section). Its
// generalized derivative (the 2x2 tangential block, its coupling to the normal through s) against
// central differences on every branch of every law, the stick/slip circle |z| = s and the cone's
// apex included; a 2D state laid along any tangent direction gives the 2D kernel, values and
// derivatives; the Alart-Curnier functions vanish on the 3D Signorini-Coulomb states.
#include "contact/contact_kernel.hpp"
#include "core/error.hpp"
#include "kernel_laws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace sig {
namespace {

using Kernel3 = ContactKernelIn<3>;
using Variables3 = NodeVariablesIn<3>;
using Col = KernelColumns<3>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

constexpr double kEps = std::numeric_limits<double>::epsilon();
const std::vector<double> kAugmentations = {1e-2, 1.0, 1e2, 1e4};

/// (N, T1, T2, C_n, C_t1, C_t2) and their derivatives in (q_n, q_t1, q_t2, lambda, t1, t2).
Vector6 outputs(const Kernel3& k) {
  Vector6 v;
  v << k.normal, k.tangential, k.complementarity;
  return v;
}
Matrix6 derivatives(const Kernel3& k) {
  Matrix6 d;
  d << k.d_force, k.d_complementarity;
  return d;
}
bool same_branch(const Kernel3& a, const Kernel3& b) {
  return a.wall_active == b.wall_active && a.stick == b.stick &&
         (a.slip.norm() > 0) == (b.slip.norm() > 0) && a.compliance_slope == b.compliance_slope &&
         (a.bound > 0) == (b.bound > 0);
}

Variables3 with(Variables3 x, int variable, double delta) {
  double* v[] = {&x.q_n, &x.q_t[0], &x.q_t[1], &x.lambda, &x.t[0], &x.t[1]};
  *v[variable] += delta;
  return x;
}

Eigen::Vector2d direction(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

/// Central differences in each variable with a step that keeps x's branch. The slip side is
/// smooth, not affine (s z / |z|): the step is a small part of |z| and, in the slips, of |z| / r.
void expect_derivatives(const ContactLaw& law, const Variables3& x, double r,
                        const std::string& where) {
  const Kernel3 k = contact_kernel(law, x, r, r);
  const Matrix6 analytic = derivatives(k);
  const double z = (x.t + r * x.q_t).norm();
  const double scale = 1 + std::abs(x.q_n) * r + x.q_t.norm() * r + std::abs(x.lambda) + x.t.norm();
  for (int j = 0; j < 6; ++j) {
    const bool slip_variable = j == Col::q_t || j == Col::q_t + 1;
    double h = 1e-4 * std::min(1.0, 0.1 + z) / (slip_variable ? 1 + r : 1.0);
    Kernel3 plus, minus;
    for (; h > 1e-14; h /= 4) {
      plus = contact_kernel(law, with(x, j, h), r, r);
      minus = contact_kernel(law, with(x, j, -h), r, r);
      if (same_branch(plus, k) && same_branch(minus, k) &&
          same_coefficient_piece(law, x.q_n, with(x, j, h).q_n) &&
          same_coefficient_piece(law, x.q_n, with(x, j, -h).q_n))
        break;
    }
    ASSERT_GT(h, 1e-14) << where << ": no step stays on the branch in variable " << j;
    const Vector6 fd = (outputs(plus) - outputs(minus)) / (2 * h);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(analytic(i, j), fd[i],
                  1e-6 * (1 + std::abs(analytic(i, j))) + 16 * kEps * scale / h)
          << where << ": output " << i << " variable " << j;
  }
}

/// Points on every branch: off, on and beyond the wall; inside the disc and beyond it in
/// several directions of the tangent plane.
std::vector<Variables3> points_of_every_branch() {
  std::vector<Variables3> points;
  for (double q_n : {-0.3, 0.1, 0.25, 0.9})
    for (double lambda : {-2.0, 0.75, 3.0}) // 0.7: on the wall at q_n = -0.3, r = 1
      for (const Eigen::Vector2d& q_t : {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.02, -0.01),
                                         Eigen::Vector2d(-0.5, 0.3), Eigen::Vector2d(0.6, 0.6)})
        for (const Eigen::Vector2d& t :
             {Eigen::Vector2d(-1.5, 0.4), Eigen::Vector2d(0.1, 0.05), Eigen::Vector2d(2.0, -1.0)})
          points.push_back({q_n, q_t, lambda, t});
  return points;
}

class EveryLaw3d : public ::testing::TestWithParam<KernelCase> {};

TEST_P(EveryLaw3d, DerivativesOnEveryBranch) {
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  for (double r : kAugmentations)
    for (const Variables3& x : points_of_every_branch())
      expect_derivatives(law, x, r,
                         describe(law) + " r " + std::to_string(r) + " q_n " +
                             std::to_string(x.q_n) + " lambda " + std::to_string(x.lambda));
}

TEST_P(EveryLaw3d, DerivativesOnBothSidesOfTheStickSlipCircle) {
  // |z| = s crossed along z's own direction, in several directions of the tangent plane.
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  if (!law.has_friction()) return;
  for (double r : kAugmentations)
    for (double angle : {0.3, 2.0, 4.4})
      for (double q_n : {0.1, 0.45})
        for (double offset : {-1e-3, -1e-6, 1e-6, 1e-3}) {
          Variables3 x{q_n, 0.03 * direction(angle + 1), 0.8, Eigen::Vector2d::Zero()};
          const double s = contact_kernel(law, x, r, r).bound;
          if (s <= 0) continue;
          x.t = (s + offset) * direction(angle) - r * x.q_t;
          expect_derivatives(law, x, r,
                             describe(law) + " circle, r " + std::to_string(r) + " angle " +
                                 std::to_string(angle) + " offset " + std::to_string(offset));
        }
}

TEST_P(EveryLaw3d, OnTheCircleTheDerivativeIsTheStickSides) {
  // On |z| = s the kink belongs to stick: inward along z the one-sided difference is the
  // derivative; along the circle's tangent both sides agree (the slip side's s (I - e e^T) / |z|
  // is the identity there), so the central difference is the derivative too.
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  if (!law.has_friction()) return;
  for (double r : kAugmentations)
    for (double angle : {0.3, 2.0, 4.4}) {
      Variables3 x{0.45, Eigen::Vector2d::Zero(), 0.8, Eigen::Vector2d::Zero()};
      const double s = contact_kernel(law, x, r, r).bound;
      x.t = s * (1 - 4 * kEps) * direction(angle); // on the circle, |e| = 1 to round-off
      const Kernel3 k = contact_kernel(law, x, r, r);
      EXPECT_TRUE(k.stick) << describe(law);
      const Matrix6 d = derivatives(k);
      const Eigen::Vector2d inward = -direction(angle), along = direction(angle + M_PI / 2);
      for (double h : {1e-8, 1e-5}) {
        const auto moved = [&](const Eigen::Vector2d& dir, double length) {
          Variables3 y = x;
          y.t += length * dir;
          return outputs(contact_kernel(law, y, r, r));
        };
        const Vector6 one_sided = (moved(inward, h) - outputs(k)) / h;
        const Vector6 central = (moved(along, h) - moved(along, -h)) / (2 * h);
        const Vector6 d_inward = d.middleCols<2>(Col::t) * inward;
        const Vector6 d_along = d.middleCols<2>(Col::t) * along;
        for (int i = 0; i < 6; ++i) {
          EXPECT_NEAR(d_inward[i], one_sided[i],
                      1e-6 * (1 + std::abs(d_inward[i])) + 64 * kEps * (1 + s) / h)
              << describe(law) << " output " << i;
          EXPECT_NEAR(d_along[i], central[i],
                      1e-5 * (1 + std::abs(d_along[i])) + 64 * kEps * (1 + s) / h)
              << describe(law) << " output " << i;
        }
      }
    }
}

TEST_P(EveryLaw3d, AlongOneTangentItIsThe2dKernel) {
  // A 2D state laid along the unit tangent e: N, s, C_n and the statuses of 2D, T = T_2d e and
  // C_t = C_t,2d e, the 2D derivatives in the direction e, and across e the stick side's
  // identity or the slip side's s / |z| (the disc's curvature, which a 2D body does not have).
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  for (double r : kAugmentations)
    for (double q_n : {-0.3, 0.1, 0.25, 0.9})
      for (double lambda : {-2.0, 0.0, 0.7, 3.0})
        for (double q_t : {-0.5, 0.0, 0.02, 0.6})
          for (double t : {-1.5, 0.1, 2.0})
            for (double angle : {0.0, 0.7, 2.5}) {
              const Eigen::Vector2d e = direction(angle), across = direction(angle + M_PI / 2);
              // On the circle itself |z e| = |z| only to round-off: a kink, tested above.
              const double bound = contact_kernel(law, {q_n, q_t, lambda, t}, r, r).bound;
              if (std::abs(std::abs(t + r * q_t) - bound) < 1e-12 * (1 + bound)) continue;
              const ContactKernel k2 = contact_kernel(law, {q_n, q_t, lambda, t}, r, r);
              const Kernel3 k3 = contact_kernel(law, Variables3{q_n, q_t * e, lambda, t * e}, r, r);
              const std::string where = describe(law) + " r " + std::to_string(r);
              const double tol = 1e-13 * (1 + r) * (1 + std::abs(lambda) + std::abs(t));
              EXPECT_EQ(k3.normal, k2.normal) << where;
              EXPECT_EQ(k3.bound, k2.bound) << where;
              EXPECT_EQ(k3.complementarity[0], k2.complementarity[0]) << where;
              EXPECT_EQ(k3.wall_active, k2.wall_active) << where;
              EXPECT_EQ(k3.stick, k2.stick) << where;
              EXPECT_LT((k3.slip - k2.slip * e).norm(), 1e-15) << where;
              EXPECT_LT((k3.tangential - k2.tangential * e).norm(), tol) << where;
              EXPECT_LT((k3.complementarity.tail<2>() - k2.complementarity[1] * e).norm(), tol)
                  << where;
              // The 2D columns: q_n, lambda as they are; q_t and t along e.
              for (int i = 0; i < 2; ++i) {
                const auto rows3 = i == 0 ? k3.d_force : k3.d_complementarity;
                const auto rows2 = i == 0 ? k2.d_force : k2.d_complementarity;
                for (int row = 0; row < 2; ++row) {
                  const auto project = [&](const Eigen::Matrix<double, 1, 6>& r3, int c3) {
                    const Eigen::Vector2d pair = r3.segment<2>(c3).transpose();
                    return pair.dot(e);
                  };
                  const Eigen::Matrix<double, 1, 6> r3 =
                      row == 0 ? Eigen::Matrix<double, 1, 6>(rows3.row(0))
                               : Eigen::Matrix<double, 1, 6>(e.transpose() * rows3.bottomRows<2>());
                  EXPECT_NEAR(r3(Col::q_n), rows2(row, kQn), tol) << where << " row " << row;
                  EXPECT_NEAR(r3(Col::lambda), rows2(row, kLambda), tol) << where;
                  EXPECT_NEAR(project(r3, Col::q_t), rows2(row, kQt), tol) << where;
                  EXPECT_NEAR(project(r3, Col::t), rows2(row, kT), tol) << where;
                }
              }
              if (!law.has_friction()) continue;
              const Eigen::Vector2d z = t * e + r * q_t * e;
              const double curvature = k3.stick ? 1.0 : z.norm() > 0 ? k3.bound / z.norm() : 0.0;
              EXPECT_NEAR(across.dot(k3.d_force.bottomRows<2>().middleCols<2>(Col::t) * across),
                          curvature, 1e-13 * (1 + curvature))
                  << where;
            }
}

TEST_P(EveryLaw3d, OnItsOwnBranchTheHeldKernelIsTheKernel) {
  const ContactLaw law = law_of(GetParam().normal, GetParam().friction);
  for (double r : kAugmentations)
    for (const Variables3& x : points_of_every_branch()) {
      const Kernel3 k = contact_kernel(law, x, r, r);
      const Kernel3 held = contact_kernel(law, x, r, r, branch_of(k));
      EXPECT_EQ(outputs(held), outputs(k)) << describe(law) << " r " << r;
      EXPECT_EQ(derivatives(held), derivatives(k)) << describe(law) << " r " << r;
      EXPECT_TRUE(branch_of(held) == branch_of(k));
    }
}

INSTANTIATE_TEST_SUITE_P(Laws, EveryLaw3d, ::testing::ValuesIn(every_kernel_case()));

TEST(ContactKernel3d, ZerosAreTheSignoriniCoulombStates) {
  // In contact and sticking inside the cone, slipping on its edge against the slip's direction,
  // off the wall and free: C = 0 exactly; a penetration or a pull is not a zero.
  const ContactLaw law = law_of(NormalLaw::signorini, FrictionLaw::coulomb);
  const double g = law.depth;
  for (double r : kAugmentations)
    for (double angle : {0.0, 1.1, 3.9}) {
      const Eigen::Vector2d e = direction(angle);
      EXPECT_EQ(contact_kernel(law, Variables3{g, Eigen::Vector2d::Zero(), 2.0, 0.3 * e}, r, r)
                    .complementarity.norm(),
                0.0);
      // Slipping by 0.2 along e under the full friction force mu lambda = 0.6 along e.
      EXPECT_NEAR(
          contact_kernel(law, Variables3{g, 0.2 * e, 2.0, 0.6 * e}, r, r).complementarity.norm(),
          0.0, 1e-15 * (1 + r));
      EXPECT_EQ(
          contact_kernel(law, Variables3{g - 0.1, 5.0 * e, 0.0, Eigen::Vector2d::Zero()}, r, r)
              .complementarity.norm(),
          0.0);
      EXPECT_GT(std::abs(contact_kernel(law,
                                        Variables3{g + 0.1, Eigen::Vector2d::Zero(), 0.0,
                                                   Eigen::Vector2d::Zero()},
                                        r, r)
                             .complementarity[0]),
                0);
      // A friction force beyond the cone, or not opposed to the slip, is not a zero.
      EXPECT_GT(contact_kernel(law, Variables3{g, Eigen::Vector2d::Zero(), 2.0, 0.7 * e}, r, r)
                    .complementarity.tail<2>()
                    .norm(),
                0);
      EXPECT_GT(contact_kernel(law, Variables3{g, 0.2 * e, 2.0, 0.6 * direction(angle + 1)}, r, r)
                    .complementarity.tail<2>()
                    .norm(),
                0);
    }
}

TEST(ContactKernel3d, TheForceStaysInTheCone) {
  // |T| <= s everywhere, T along z beyond the disc: the projection on the disc of radius s.
  const ContactLaw law = law_of(NormalLaw::compliance, FrictionLaw::coulomb);
  for (double r : kAugmentations)
    for (const Variables3& x : points_of_every_branch()) {
      const Kernel3 k = contact_kernel(law, x, r, r);
      EXPECT_LE(k.tangential.norm(), k.bound * (1 + 1e-15) + (k.stick ? k.tangential.norm() : 0));
      const Eigen::Vector2d z = x.t + r * x.q_t;
      if (k.stick) {
        EXPECT_LE(z.norm(), k.bound);
        EXPECT_EQ(k.tangential, z);
      } else if (z.norm() > 0) {
        EXPECT_NEAR(k.tangential.norm(), k.bound, 1e-14 * (1 + k.bound));
        EXPECT_NEAR(k.tangential.dot(z), k.bound * z.norm(), 1e-12 * (1 + k.bound * z.norm()));
      }
    }
}

TEST(ContactKernel3d, TheConeApexOnTheWallSticks) {
  // A node just touching at rest (s = mu N = 0, z = 0) sticks, as in 2D: its slip is imposed.
  const ContactLaw coulomb = law_of(NormalLaw::signorini, FrictionLaw::coulomb);
  for (double r : kAugmentations) {
    const Kernel3 k = contact_kernel(
        coulomb, Variables3{coulomb.depth, Eigen::Vector2d::Zero(), 0.0, Eigen::Vector2d::Zero()},
        r, r);
    EXPECT_TRUE(k.wall_active);
    EXPECT_EQ(k.bound, 0.0);
    EXPECT_TRUE(k.stick);
    EXPECT_EQ(k.d_force.bottomRows<2>().middleCols<2>(Col::q_t), r * Eigen::Matrix2d::Identity());
  }
  // Off the wall the apex slips with no direction: T = 0, nothing held.
  const Kernel3 off = contact_kernel(
      coulomb,
      Variables3{coulomb.depth - 0.1, Eigen::Vector2d::Zero(), 0.0, Eigen::Vector2d::Zero()}, 1, 1);
  EXPECT_FALSE(off.stick);
  EXPECT_EQ(off.slip, Eigen::Vector2d::Zero());
  EXPECT_EQ(off.tangential, Eigen::Vector2d::Zero());
  // mu1 and mu2 at rest on a compliance: s = 0 with ds/dq_n = 0, but a press raises s (2D's
  // test): the apex sticks, its slip imposed in both tangents.
  for (const FrictionLaw f : {FrictionLaw::mu1, FrictionLaw::mu2}) {
    const ContactLaw law = law_of(NormalLaw::compliance_unilateral, f);
    const Variables3 rest{0.0, Eigen::Vector2d::Zero(), 0.0, Eigen::Vector2d::Zero()};
    const Kernel3 k = contact_kernel(law, rest, 1, 1);
    EXPECT_EQ(k.bound, 0.0);
    EXPECT_TRUE(k.stick) << to_string(f);
    EXPECT_EQ(k.d_force.bottomRows<2>().middleCols<2>(Col::q_t), Eigen::Matrix2d::Identity());
  }
}

TEST_P(EveryLaw3d, AHeldTangentialComponentSticksAndTheOtherKeepsTheLawOfItsLine) {
  // A roller on a 3D contact node holds one tangent of its frame (ContactLaw::held_tangent): that
  // component sticks at its held slip whatever its force; the other keeps the friction law on its
  // line, the 2D kernel's at the same (q_n, q_t, lambda, t); the derivative is exact on every
  // branch, the free component's kink |z_j| = s crossed from both sides.
  for (int held : {0, 1}) {
    ContactLaw law = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
    const ContactLaw plane_law = law; // the 2D kernel of the free line
    law.held_tangent[held] = true;
    law.held_slip[held] = 0.05;
    const int free = 1 - held;
    std::vector<Variables3> points = points_of_every_branch();
    for (double r : kAugmentations) {
      for (double offset : {-1e-3, 1e-3}) { // either side of the free line's kink
        Variables3 x{0.45, Eigen::Vector2d(0.03, -0.02), 0.8, Eigen::Vector2d(0.3, -0.7)};
        const double s = contact_kernel(law, x, r, r).bound;
        if (s <= 0) continue;
        x.t[free] = s + offset - r * x.q_t[free];
        points.push_back(x);
      }
      for (const Variables3& x : points) {
        const std::string where = describe(law) + " r " + std::to_string(r) + " q_n " +
                                  std::to_string(x.q_n) + " t " + std::to_string(x.t[free]);
        const Kernel3 k = contact_kernel(law, x, r, r);
        EXPECT_DOUBLE_EQ(k.tangential[held], x.t[held] + r * (x.q_t[held] - 0.05)) << where;
        const ContactKernel line =
            contact_kernel(plane_law, {x.q_n, x.q_t[free], x.lambda, x.t[free]}, r, r);
        EXPECT_DOUBLE_EQ(k.normal, line.normal) << where;
        if (law.friction != FrictionLaw::none) {
          EXPECT_DOUBLE_EQ(k.tangential[free], line.tangential) << where;
          EXPECT_EQ(k.stick, line.stick) << where;
          EXPECT_EQ(k.slip[free], line.slip) << where;
        }
        EXPECT_EQ(k.slip[held], 0.0) << where;
        // A point on the free line's kink itself has no branch to difference on.
        const double z = x.t[free] + r * x.q_t[free];
        if (std::abs(std::abs(z) - k.bound) > 1e-9 * (1 + k.bound))
          expect_derivatives(law, x, r, where);
      }
    }
  }
  // Both held: a stick in both components, whatever the friction law.
  ContactLaw both = law_of(GetParam().normal, GetParam().friction, GetParam().bound);
  both.held_tangent = {true, true};
  both.held_slip = {0.05, -0.02};
  const Variables3 x{0.1, Eigen::Vector2d(0.3, 0.4), 0.8, Eigen::Vector2d(5.0, -6.0)};
  const Kernel3 k = contact_kernel(both, x, 2, 2);
  EXPECT_TRUE(k.stick);
  EXPECT_EQ(k.tangential, x.t + 2 * (x.q_t - Eigen::Vector2d(0.05, -0.02)));
}

TEST(ContactKernel3d, AHeldNormalIsABilateralWall) {
  ContactLaw bilateral = law_of(NormalLaw::signorini, FrictionLaw::none);
  bilateral.held_normal = true;
  const Kernel3 k = contact_kernel(
      bilateral, Variables3{0.0, Eigen::Vector2d::Zero(), -1.0, Eigen::Vector2d::Zero()}, 2, 2);
  EXPECT_TRUE(k.held);
  EXPECT_EQ(k.wall, -1.0 - 2 * bilateral.depth);
}

} // namespace
} // namespace sig
