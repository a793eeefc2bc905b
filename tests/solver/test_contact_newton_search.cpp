// The step length of the contact Newton driver (contact_newton.hpp): its residual is the natural
// one (each node's complementarity scaled by its bulk stiffness, not by the method's
// parameter), so a full step whose only fault is a node it leaves penetrating (the next test
// puts that node on the wall) is taken whatever the augmentation, on a linear and on a
// nonlinear bulk; a step that raises the residual more than tenfold over the recent iterates is
// shortened until it does not; a step that raised it and was not repaid within kWatchSteps more
// steps (more while the path's rate promises it) is undone (the watchdog). A scripted bulk whose
// residual is the Newton step's linear model makes the full step exact for the system the step
// linearized.
#include "along_step_bulk.hpp"
#include "solver/contact_newton.hpp"
#include "solver/newton_guard.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace sig {
namespace {

/// Two contact nodes: node 0 on the obstacle surface (tested on the wall), node 1 off it by
/// 0.01, which the step moves by `overshoot` (penetrating overshoot - 0.01 at the full step).
/// The equilibrium residual falls linearly to 0 along the step: alpha = 1 solves the linearized
/// system exactly.
class OvershootingBulk final : public test::AlongStepBulk {
public:
  double overshoot = 0.02;

  Eigen::VectorXd penetration() const override {
    return Eigen::Vector2d(0.0, -0.01 + overshoot * alpha_);
  }
  double equilibrium_residual(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return 1.0 - alpha_;
  }
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd&) override {
    EXPECT_TRUE(conditions[0].normal.imposed);
    EXPECT_FALSE(conditions[1].normal.imposed);
    StepSolution s;
    s.normal_increment = Eigen::Vector2d(0.0, overshoot);
    s.normal_force = Eigen::Vector2d(1.0, 0.0); // node 0's reaction
    s.tangential_force = Eigen::VectorXd::Zero(2);
    return s;
  }
};

double first_step_length(const std::string& method, double parameter, bool nonlinear,
                         double overshoot = 0.02) {
  OvershootingBulk bulk;
  bulk.is_nonlinear = nonlinear;
  bulk.overshoot = overshoot;
  ContactSolverParameters p;
  p.method = method;
  p.gamma = p.r = p.c = parameter;
  if (method == "projection") p.c = 1 / parameter; // r_n = 1 / c
  const std::unique_ptr<ContactMethod> m = make_contact_method(p);
  ContactSetting setting;
  setting.law.assign(2, ContactLaw{});
  setting.weight = Eigen::VectorXd::Ones(2);
  ContactNewtonOptions options;
  options.max_iterations = 1;
  ContactIterate iterate;
  const ContactNewtonResult r = solve_contact(bulk, setting, *m, options, iterate);
  EXPECT_EQ(r.step_length.size(), 1u);
  return r.step_length.empty() ? 0.0 : r.step_length[0];
}

TEST(ContactNewtonSearch, TheFullStepIsTakenWhateverTheAugmentation) {
  // Measured with the method's r, node 1's penetration would count r x 0.01 >= 1, the whole
  // starting residual, for r >= 100, and a search would halve the step.
  for (bool nonlinear : {false, true})
    for (const char* method : {"pdas", "alm", "projection"})
      for (double r : {1.0, 1e2, 1e4, 1e6})
        EXPECT_EQ(first_step_length(method, r, nonlinear), 1.0)
            << method << " r " << r << (nonlinear ? " nonlinear" : " linear");
}

TEST(ContactNewtonSearch, AStepThatRaisesTheResidualTenfoldIsShortened) {
  // The full step drives node 1 100 deep: its residual, 100, is over ten times the first one,
  // 1. Halved to 1/16 the penetration is 6.24 and the residual 6.3: the first length below the
  // ceiling, whatever the method's parameter.
  for (bool nonlinear : {false, true})
    for (double r : {1.0, 1e4})
      EXPECT_EQ(first_step_length("pdas", r, nonlinear, 100.0), 1.0 / 16)
          << "r " << r << (nonlinear ? " nonlinear" : " linear");
}

/// A solve that starts at its solution to round-off: node 0 on the obstacle surface with no
/// force (the degenerate node of complementarity: a ball's pole arriving exactly on a time
/// level), node 1 off it. The step only moves node 0's multiplier to its reaction, 1e-4 of the
/// force scale, and the equilibrium residual is round-off, 1e-16: as a large condensed bulk's
/// (the 3D ball impact on the (0.1, 0.15) mesh: 7.07e-16 along the step, 9.0e-16 at its end),
/// it grows by 30 % along the step but for a last-digit dip at 1/64 of it, which Armijo's test
/// takes. The step is rebased at every solve (the iterate the driver keeps).
class RoundOffBulk final : public test::AlongStepBulk {
public:
  static constexpr double kFloor = 1e-16, kReaction = 1e-4;

  Eigen::VectorXd penetration() const override { return Eigen::Vector2d(0.0, -0.01); }
  double equilibrium_residual(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return alpha_ > 1.0 / 64 ? floor_ * (1 + 0.3 * alpha_) : floor_ * (1 - 1e-5 * 64 * alpha_);
  }
  double displacement_step() const override { return 0; }
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd&) override {
    EXPECT_TRUE(conditions[0].normal.imposed);
    EXPECT_FALSE(conditions[1].normal.imposed);
    floor_ = equilibrium_residual({}, {}); // the kept iterate's, from which the step starts
    alpha_ = kept_ = 0;
    StepSolution s;
    s.normal_increment = Eigen::Vector2d::Zero();
    s.normal_force = Eigen::Vector2d(kReaction, 0.0);
    s.tangential_force = Eigen::VectorXd::Zero(2);
    return s;
  }

private:
  double floor_ = kFloor;
};

TEST(ContactNewtonSearch, AResidualAtRoundOffTakesTheFullStep) {
  // Merits at round-off cannot be ranked: before, the search took 1/64 of the step at each
  // iteration, the multiplier crept towards its reaction, the relative increment stayed near
  // 1e-6 > eps and the repeated branch set was named a cycle. The full step's residual is at
  // round-off too: taken, and the next step is nothing.
  for (const char* method : {"pdas", "alm"}) {
    RoundOffBulk bulk;
    ContactSolverParameters p;
    p.method = method;
    const std::unique_ptr<ContactMethod> m = make_contact_method(p);
    ContactSetting setting;
    setting.law.assign(2, ContactLaw{});
    setting.weight = Eigen::VectorXd::Ones(2);
    ContactNewtonOptions options;
    options.eps = 1e-10; // a march's (ContactStrategyParameters)
    ContactIterate iterate;
    const ContactNewtonResult r = solve_contact(bulk, setting, *m, options, iterate);
    EXPECT_TRUE(r.converged) << method << ": " << r.failure;
    EXPECT_LE(r.iterations(), 2) << method;
    ASSERT_FALSE(r.step_length.empty()) << method;
    EXPECT_EQ(r.step_length[0], 1.0) << method;
    EXPECT_DOUBLE_EQ(r.normal_force[0], RoundOffBulk::kReaction) << method;
  }
}

/// A path of Newton steps, the bulk's state a position s along it (s = 0, 1, 2, ... the iterates):
/// node 0 far off the obstacle, node 1 off it by 0.01 at s = 0. The first step drives node 1 4
/// deep while the equilibrium residual falls from 1 to 0: the system it linearized (node 1 held
/// off the wall) is solved, the merit rises to 4, under the ceiling. The next steps (node 1 on
/// the wall, its reaction 1) bring the merit to 3 at s = 2, then along `after` (by default down
/// by 1/4 a step: above 1, where the raise started, until s = 10).
class RaisingBulk final : public test::AlongStepBulk {
public:
  std::function<double(double)> after = [](double s) { return 3 - 0.25 * (s - 2); };
  std::vector<double> solved_at; ///< the positions each step started from

  Eigen::VectorXd penetration() const override {
    const double s = position();
    return Eigen::Vector2d(-1.0, s <= 1 ? -0.01 + 4.01 * s : s <= 2 ? 4 - 4 * (s - 1) : 0.0);
  }
  double equilibrium_residual(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    const double s = position();
    return s <= 1 ? 1 - s : s <= 2 ? 3 * (s - 1) : after(s);
  }
  double displacement_step() const override { return alpha_; }
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd&) override {
    base_ = position();
    alpha_ = kept_ = 0;
    solved_at.push_back(base_);
    EXPECT_FALSE(conditions[0].normal.imposed);
    StepSolution s;
    s.normal_increment = Eigen::Vector2d(0.0, penetration_at(base_ + 1) - penetration_at(base_));
    s.normal_force = Eigen::Vector2d(0.0, conditions[1].normal.imposed ? 1.0 : 0.0);
    s.tangential_force = Eigen::VectorXd::Zero(2);
    return s;
  }
  void checkpoint() override { checkpoint_ = position(); }
  void rewind() override {
    base_ = checkpoint_;
    alpha_ = kept_ = 0;
  }

private:
  double base_ = 0;
  double position() const { return base_ + alpha_; }
  double penetration_at(double s) {
    const double keep = base_, a = alpha_;
    base_ = s;
    alpha_ = 0;
    const double q = penetration()[1];
    base_ = keep;
    alpha_ = a;
    return q;
  }
};

/// PDAS on `bulk`, `iterations` at most.
ContactNewtonResult solve_raising(RaisingBulk& bulk, int iterations = kWatchSteps + 2) {
  ContactSolverParameters p;
  p.method = "pdas";
  const std::unique_ptr<ContactMethod> m = make_contact_method(p);
  ContactSetting setting;
  setting.law.assign(2, ContactLaw{});
  setting.weight = Eigen::VectorXd::Ones(2);
  ContactNewtonOptions options;
  options.max_iterations = iterations;
  ContactIterate iterate;
  return solve_contact(bulk, setting, *m, options, iterate);
}

TEST(ContactNewtonSearch, AStepNotRepaidIsUndone) {
  // The watchdog: after the raise to 4 and kWatchSteps steps that leave the merit above 1 and
  // falling too slowly to repay it within kWatchSteps more, the
  // next iteration starts again from s = 0 (the solve's start, where the raise began), and its
  // search may no longer raise the merit: the full step (merit 4) and its halvings down to 1/8
  // (node 1 0.49 deep, the merit 1.003) raise it, 1/16 is the first that does not (0.24 deep,
  // the equilibrium residual 15/16).
  static_assert(kWatchSteps < 8, "the scripted path repays the raise at s = 10");
  RaisingBulk bulk;
  const ContactNewtonResult r = solve_raising(bulk);
  ASSERT_EQ(r.history.size(), std::size_t(kWatchSteps + 2)) << r.failure;
  std::vector<double> expected;
  for (int k = 0; k <= kWatchSteps; ++k)
    expected.push_back(k);
  expected.push_back(0.0);
  EXPECT_EQ(bulk.solved_at, expected);
  EXPECT_NEAR(r.history[0].residual, 4.0, 1e-9);
  EXPECT_NEAR(r.history[kWatchSteps].residual, 3 - 0.25 * (kWatchSteps - 1), 1e-9);
  for (int k = 0; k <= kWatchSteps; ++k)
    EXPECT_EQ(r.step_length[k], 1.0) << k;
  const IterationRecord& back = r.history.back();
  EXPECT_EQ(back.kind, 5);
  EXPECT_EQ(r.step_length.back(), 1.0 / 16);
  EXPECT_NEAR(back.residual, std::hypot(15.0 / 16, -0.01 + 4.01 / 16), 1e-12);
}

/// Positions 0, 1, ..., n - 1 (the steps of a solve that nothing undid), then `tail`.
std::vector<double> positions(int n, std::vector<double> tail = {}) {
  std::vector<double> p;
  for (int k = 0; k < n; ++k)
    p.push_back(k);
  p.insert(p.end(), tail.begin(), tail.end());
  return p;
}

TEST(ContactNewtonSearch, ARaiseFallingFastGetsAStepMore) {
  // The same raise, above 1 when the watch ends (1.2 at s = kWatchSteps + 1) but falling fast
  // (the last step's rate would repay it within kWatchSteps more): one step more, which repays
  // it (0.6): nothing undone. The unrepaid path's rate, 2.25 / 2.5, would not (2.25 x 0.9^4 > 1).
  RaisingBulk bulk;
  const double descent = 1.8 / (kWatchSteps - 1);
  bulk.after = [descent](double s) { return std::max(0.0, 3 - descent * (s - 2)); };
  ASSERT_TRUE(rate_repays(1.2, 1.2 + descent, 1.0)) << "the path must promise the repayment";
  const ContactNewtonResult r = solve_raising(bulk);
  ASSERT_EQ(r.history.size(), std::size_t(kWatchSteps + 2)) << r.failure;
  EXPECT_EQ(bulk.solved_at, positions(kWatchSteps + 2));
  EXPECT_NEAR(r.history[kWatchSteps].residual, 1.2, 1e-12);
  EXPECT_NEAR(r.history[kWatchSteps + 1].residual, 1.2 - descent, 1e-12);
  for (std::size_t k = 0; k < r.history.size(); ++k)
    EXPECT_NE(r.history[k].kind, 5) << k;
}

TEST(ContactNewtonSearch, ARaiseThatLevelsOffIsUndoneAfterTheLastExtension) {
  // The merit 1 + 2^(3 - s) after s = 2 never repays the raise, yet each step's rate promises
  // it: kWatchSteps extensions, then the return to s = 0, 2 kWatchSteps steps after the raise.
  RaisingBulk bulk;
  bulk.after = [](double s) { return 1 + std::pow(2.0, 3 - s); };
  const ContactNewtonResult r = solve_raising(bulk, 2 * kWatchSteps + 2);
  ASSERT_EQ(r.history.size(), std::size_t(2 * kWatchSteps + 2)) << r.failure;
  EXPECT_EQ(bulk.solved_at, positions(2 * kWatchSteps + 1, {0.0}));
  for (int k = 0; k + 1 < 2 * kWatchSteps + 1; ++k)
    EXPECT_NE(r.history[k].kind, 5) << k;
  EXPECT_EQ(r.history.back().kind, 5);
}

TEST(ContactNewtonSearch, AStepRepaidInTimeStands) {
  // The same raise, crawling down (3 - (s - 2) / 10: too slowly for the rate to promise
  // anything) until the last step the watch allows drops it to 1/2: nothing undone, every step
  // starts where the last one ended, every one of full length. A watch one step shorter would
  // have returned.
  RaisingBulk bulk;
  bulk.after = [](double s) { return s < kWatchSteps + 1 ? 3 - 0.1 * (s - 2) : 0.5; };
  ASSERT_FALSE(rate_repays(bulk.after(kWatchSteps), bulk.after(kWatchSteps - 1), 1.0));
  const ContactNewtonResult r = solve_raising(bulk);
  ASSERT_EQ(r.history.size(), std::size_t(kWatchSteps + 2)) << r.failure;
  EXPECT_EQ(bulk.solved_at, positions(kWatchSteps + 2));
  EXPECT_GT(r.history[kWatchSteps - 1].residual, 1.0);
  EXPECT_NEAR(r.history[kWatchSteps].residual, 0.5, 1e-12);
  for (std::size_t k = 0; k < r.history.size(); ++k) {
    EXPECT_NE(r.history[k].kind, 5) << k;
    EXPECT_EQ(r.step_length[k], 1.0) << k;
  }
}

} // namespace
} // namespace sig
