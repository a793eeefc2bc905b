// The convexification loop (solver/convexification.hpp) on the single-node problem of
// ALGORITHMS.md 1.6 (check 1): one P1 triangle's stiffnesses k_x = mu, k_y = lambda + 2 mu
// (E = 200, nu = 0.3), a node pressed by P = 200 onto compliance c = 10 with its wall at g = 0.5,
// pushed sideways by F_x, nonmonotone friction mu(r) = (a - b) exp(-alpha r) + b bounded by the
// compliance pressure (4.6). Exact: the node is on the wall (CU), lambda = P - (k_y + c) g, and it
// sticks if |F_x| <= a c g, else slips by the fixed point r* of k_x r + c g mu(r) = |F_x|; the
// loop is the scalar iteration r(m+1) = (|F_x| - c g mu(r(m))) / k_x, whose outer count the
// loop's must equal with the same stopping test.
#include "core/error.hpp"
#include "scene4_law.hpp"
#include "solver/condensed_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sig {
namespace {

constexpr double kE = 200, kNu = 0.3;
constexpr double kMu = kE / (2 * (1 + kNu));                       // k_x = 76.923
constexpr double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)); // k_y = lambda + 2 mu
constexpr double kKx = kMu, kKy = kLambda + 2 * kMu;
constexpr double kCn = 10, kG = 0.5, kP = 200;

ContactLaw nonmonotone(double a, double b, double alpha) {
  return test::compliance_nonmonotone(kCn, kG, a, b, alpha);
}

struct SingleNode {
  CondensedProblem problem;
  ContactSetting setting;
};

SingleNode single_node(double Fx, const ContactLaw& law) {
  SingleNode n;
  n.problem.S = Eigen::Vector2d(kKx, kKy).asDiagonal();
  n.problem.f = Eigen::Vector2d(Fx, kP);
  n.problem.tangential_dof = {0};
  n.problem.normal_dof = {1};
  n.problem.gap = Eigen::VectorXd::Zero(1);
  n.setting.law = {law};
  n.setting.weight = Eigen::VectorXd::Ones(1);
  return n;
}

ContactSolverParameters inner(const std::string& method) {
  ContactSolverParameters p;
  p.method = method;
  p.r = p.gamma = p.c = method == "projection" ? 1e-2 : 100;
  p.eps = 1e-13;
  return p;
}

CondensedSolution solve(const SingleNode& n, const std::string& method,
                        const ConvexificationOptions& options) {
  return solve_condensed_contact(n.problem, n.setting, inner(method), {}, {options, {}, {}, {}});
}

/// The fixed point r* of k_x r + c g mu(r) = F (F > c g a), by bisection on [0, (F - c g b) /
/// k_x], where the left side goes from below F to above it (a single root here).
double fixed_point(double F, const ContactLaw& law) {
  double lo = 0, hi = (F - kCn * kG * law.b) / kKx;
  for (int k = 0; k < 200; ++k) {
    const double r = 0.5 * (lo + hi);
    (kKx * r + kCn * kG * friction_coefficient(law, r) < F ? lo : hi) = r;
  }
  return 0.5 * (lo + hi);
}

/// The scalar iteration with the loop's test (the same norms: u = (r, g) Euclidean, xi = (N, T)
/// with N = P - k_y g): the number of convex solves it needs from rest.
int scalar_count(double F, const ContactLaw& law, double eps) {
  const double N = kP - kKy * kG;
  double mu = law.a, r_before = 0, T_before = 0;
  for (int k = 1; k < 1000; ++k) {
    const double r = (F - kCn * kG * mu) / kKx, T = kCn * kG * mu;
    if (k >= 2 && std::abs(r - r_before) <= eps * std::hypot(r_before, kG) &&
        std::abs(T - T_before) <= eps * std::hypot(N, T_before))
      return k;
    r_before = r;
    T_before = T;
    mu = friction_coefficient(law, r);
  }
  return -1;
}

class EveryExactMethod : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryExactMethod, SlipReachesTheFixedPointInTheScalarCount) {
  for (double alpha : {1.0, 100.0}) {
    const ContactLaw law = nonmonotone(1, 0.5, alpha);
    const double F = 6, r_star = fixed_point(F, law);
    ConvexificationOptions options;
    options.eps = 1e-5;
    const CondensedSolution s = solve(single_node(F, law), GetParam(), options);
    ASSERT_TRUE(s.convexification.has_value());
    const ConvexificationResult& loop = *s.convexification;
    ASSERT_TRUE(loop.converged) << GetParam() << " alpha " << alpha << ": " << loop.failure;
    EXPECT_EQ(loop.outer_iterations(), scalar_count(F, law, options.eps)) << alpha;
    // CU: on the wall with lambda = P - (k_y + c) g; S+ with T = c g mu(r) at the fixed point.
    EXPECT_NEAR(s.w[1], kG, 1e-12);
    EXPECT_EQ(s.contact.normal_status[0], NormalStatus::unilateral);
    EXPECT_NEAR(s.contact.normal_force[0], kP - kKy * kG, 1e-9);
    EXPECT_NEAR(s.contact.normal_force[0] - kCn * kG, 60.3846153846, 1e-9); // the wall's lambda
    EXPECT_EQ(s.contact.friction_status[0], FrictionStatus::slip_forward);
    // The loop stops within eps of the fixed point: |r - r*| <= G' / (1 - G') |r(m+1) - r(m)|.
    EXPECT_NEAR(s.w[0], r_star, 1e-5 * r_star) << alpha;
    EXPECT_NEAR(loop.mu[0], friction_coefficient(law, r_star), 1e-6) << alpha;
    EXPECT_NEAR(s.contact.tangential_force[0], kCn * kG * loop.mu[0], 1e-9);
    // Every convex solve's inner count is recorded; their sum is the inner history.
    int inner_total = 0;
    for (const OuterRecord& r : loop.history) {
      EXPECT_TRUE(r.inner_converged);
      inner_total += r.inner_iterations;
    }
    EXPECT_EQ(inner_total, loop.inner_iterations());
  }
  // ALGORITHMS.md 1.6's values of the fixed point (a tight eps: the point itself).
  ConvexificationOptions tight;
  tight.eps = 1e-13;
  const CondensedSolution one = solve(single_node(6, nonmonotone(1, 0.5, 1)), GetParam(), tight);
  EXPECT_NEAR(one.w[0], 0.01343367, 1e-8);
  EXPECT_NEAR(one.contact.tangential_force[0], 4.966640, 1e-6);
  const CondensedSolution hundred =
      solve(single_node(6, nonmonotone(1, 0.5, 100)), GetParam(), tight);
  EXPECT_NEAR(hundred.w[0], 0.04514412, 1e-8);
  EXPECT_NEAR(hundred.contact.tangential_force[0], 2.527375, 1e-6);
}

TEST_P(EveryExactMethod, StickBelowTheBoundNeedsTwoSolves) {
  // |F_x| = 4 < a c g = 5: the node sticks, mu stays a, and the second solve repeats the first.
  const CondensedSolution s = solve(single_node(4, nonmonotone(1, 0.5, 1)), GetParam(), {});
  ASSERT_TRUE(s.convexification && s.convexification->converged);
  EXPECT_EQ(s.convexification->outer_iterations(), 2);
  EXPECT_EQ(s.contact.friction_status[0], FrictionStatus::stick);
  EXPECT_NEAR(s.w[0], 0.0, 1e-13);
  EXPECT_NEAR(s.contact.tangential_force[0], 4.0, 1e-10);
  EXPECT_EQ(s.convexification->mu[0], 1.0);
}

INSTANTIATE_TEST_SUITE_P(Convexification, EveryExactMethod,
                         ::testing::Values("alm", "pdas", "projection"));

// The same node in 3D, pushed along an oblique direction e of its tangent plane: isotropic
// stiffness k_x in the plane, so it slips along e by the 2D fixed point r*, the loop measuring the
// slip's magnitude |w_t| and the tangential forces' (contact_bulk.hpp: two per node, flat), and
// it needs the 2D count of convex solves.
TEST(Convexification, ANodeOfA3DBodySlipsToThe2DFixedPoint) {
  const ContactLaw law = nonmonotone(1, 0.5, 100);
  const double F = 6, r_star = fixed_point(F, law);
  const Eigen::Vector2d e(0.6, -0.8);
  CondensedProblem problem;
  problem.S = Eigen::Vector3d(kKx, kKx, kKy).asDiagonal();
  problem.f = Eigen::Vector3d(F * e.x(), F * e.y(), kP);
  problem.tangential_dof = {0, 1};
  problem.normal_dof = {2};
  problem.gap = Eigen::VectorXd::Zero(1);
  ContactSetting setting;
  setting.law = {law};
  setting.weight = Eigen::VectorXd::Ones(1);
  ConvexificationOptions options;
  options.eps = 1e-5;
  for (const char* method : {"alm", "pdas"}) {
    const CondensedSolution s =
        solve_condensed_contact(problem, setting, inner(method), {}, {options, {}, {}, {}});
    ASSERT_TRUE(s.convexification && s.convexification->converged)
        << method << ": " << (s.convexification ? s.convexification->failure : "no loop");
    EXPECT_EQ(s.convexification->outer_iterations(), scalar_count(F, law, options.eps)) << method;
    EXPECT_NEAR((s.w.head<2>() - r_star * e).norm(), 0.0, 1e-5 * r_star) << method;
    EXPECT_NEAR(s.w[2], kG, 1e-12) << method;
    ASSERT_EQ(s.contact.tangential_force.size(), 2);
    EXPECT_NEAR((s.contact.tangential_force - kCn * kG * s.convexification->mu[0] * e).norm(), 0.0,
                1e-9)
        << method;
    EXPECT_NEAR(s.convexification->mu[0], friction_coefficient(law, r_star), 1e-6) << method;
  }
}

TEST(Convexification, EqualCoefficientsAreCoulomb) {
  // a = b: mu is constant, the loop's second solve repeats the first, which is Coulomb's.
  ContactLaw same = nonmonotone(0.8, 0.8, 7);
  ContactLaw coulomb = same;
  coulomb.friction = FrictionLaw::coulomb;
  coulomb.a = coulomb.b = coulomb.alpha = 0;
  for (double F : {3.0, 6.0}) {
    const CondensedSolution n = solve(single_node(F, same), "pdas", {});
    const CondensedSolution c = solve_condensed_contact(
        single_node(F, coulomb).problem, single_node(F, coulomb).setting, inner("pdas"));
    ASSERT_TRUE(n.convexification && n.convexification->converged);
    EXPECT_FALSE(c.convexification.has_value());
    EXPECT_EQ(n.convexification->outer_iterations(), 2);
    EXPECT_NEAR((n.w - c.w).norm(), 0.0, 1e-14);
    EXPECT_EQ(n.contact.friction_status, c.contact.friction_status);
    EXPECT_NEAR(n.contact.tangential_force[0], c.contact.tangential_force[0], 1e-12);
  }
}

TEST(Convexification, RelaxationAndStartReachTheSameFixedPoint) {
  const ContactLaw law = nonmonotone(1, 0.5, 1);
  const double r_star = fixed_point(6, law);
  ConvexificationOptions plain, relaxed, slipped;
  plain.eps = relaxed.eps = slipped.eps = 1e-10;
  relaxed.relaxation = 0.5;
  slipped.start = ConvexificationStart::slipped;
  const CondensedSolution a = solve(single_node(6, law), "pdas", plain);
  const CondensedSolution b = solve(single_node(6, law), "pdas", relaxed);
  const CondensedSolution c = solve(single_node(6, law), "pdas", slipped);
  for (const CondensedSolution* s : {&a, &b, &c}) {
    ASSERT_TRUE(s->convexification->converged) << s->convexification->failure;
    EXPECT_NEAR(s->w[0], r_star, 1e-8 * r_star);
  }
  // Halving each correction of a contracting, monotone iteration costs outer iterations.
  EXPECT_GT(b.convexification->outer_iterations(), a.convexification->outer_iterations());
  // From mu = b the first solve slips by (F - c g b) / k_x.
  EXPECT_EQ(c.convexification->history.front().slip, 1);
}

TEST(Convexification, NonConvergenceIsAResultWithItsHistory) {
  ConvexificationOptions options;
  options.eps = 1e-12;
  options.max_iterations = 2;
  const CondensedSolution s = solve(single_node(6, nonmonotone(1, 0.5, 1)), "pdas", options);
  ASSERT_TRUE(s.convexification.has_value());
  EXPECT_FALSE(s.convexification->converged);
  EXPECT_NE(s.convexification->failure.find("within 2 convex solves"), std::string::npos);
  EXPECT_EQ(s.convexification->outer_iterations(), 2);
  EXPECT_GT(s.convexification->history.back().displacement_change, 1e-12);
  EXPECT_TRUE(s.contact.converged); // the last convex solve itself did converge
  // An inner solve that fails stops the loop, reported.
  ContactSolverParameters starved = inner("pdas");
  starved.max_iterations = 1;
  const SingleNode node = single_node(6, nonmonotone(1, 0.5, 1));
  const CondensedSolution t =
      solve_condensed_contact(node.problem, node.setting, starved, {}, {{}, {}, {}, {}});
  EXPECT_FALSE(t.convexification->converged);
  EXPECT_NE(t.convexification->failure.find("convex solve 1 did not converge"), std::string::npos);
}

TEST(Convexification, TheSlipMeasureIsAnInput) {
  // A measure given by the caller (here twice the slip) drives the coefficients: the fixed point
  // of k_x r + c g mu(2 r) = F; a law of the slip rate refuses to run without one.
  ContactLaw law = nonmonotone(1, 0.5, 30);
  SingleNode n = single_node(6, law);
  CondensedConvexification loop;
  loop.options.eps = 1e-12;
  loop.slip = [](const Eigen::VectorXd& w) { return Eigen::VectorXd::Constant(1, 2 * w[0]); };
  const CondensedSolution s =
      solve_condensed_contact(n.problem, n.setting, inner("pdas"), {}, loop);
  ASSERT_TRUE(s.convexification->converged) << s.convexification->failure;
  const double r = s.w[0];
  EXPECT_NEAR(kKx * r + kCn * kG * friction_coefficient(law, 2 * r), 6.0, 1e-9);
  EXPECT_GT(std::abs(r - fixed_point(6, law)), 1e-4); // not the fixed point of the plain slip
  law.of = SlipMeasure::slip_rate;
  n = single_node(6, law);
  EXPECT_THROW(solve_condensed_contact(n.problem, n.setting, inner("pdas"), {}, {}), Error);
}

TEST(Convexification, BadOptionsAreErrors) {
  const SingleNode n = single_node(6, nonmonotone(1, 0.5, 1));
  for (const ConvexificationOptions& bad :
       {ConvexificationOptions{0.0, 10, 1, ConvexificationStart::rest},
        ConvexificationOptions{1e-5, 0, 1, ConvexificationStart::rest},
        ConvexificationOptions{1e-5, 10, 1.5, ConvexificationStart::rest},
        ConvexificationOptions{1e-5, 10, 0.0, ConvexificationStart::rest}})
    EXPECT_THROW(
        solve_condensed_contact(n.problem, n.setting, inner("pdas"), {}, {bad, {}, {}, {}}), Error);
}

TEST(Convexification, StatusCycles) {
  const std::vector<int> A = {1, 5}, B = {1, 6}, C = {2, 6};
  using Seen = std::vector<std::vector<int>>;
  EXPECT_EQ(status_cycle(Seen{A, B, A, B, A, B}), 2);
  EXPECT_EQ(status_cycle(Seen{C, A, B, A, B, A, B}), 2);
  EXPECT_EQ(status_cycle(Seen{A, B, C, A, B, C, A, B, C}), 3);
  EXPECT_EQ(status_cycle(Seen{A, B, A, B, A}), 0);          // two periods and a half
  EXPECT_EQ(status_cycle(Seen{A, A, A, A, A, A, A}), 0);    // settled, not cycling
  EXPECT_EQ(status_cycle(Seen{A, B, C, A, B, A, B, A}), 0); // not yet three periods
  EXPECT_EQ(status_cycle(Seen{}), 0);
}

} // namespace
} // namespace sig
