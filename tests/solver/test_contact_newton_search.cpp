// The step length of the contact Newton driver (contact_newton.hpp): its residual is the natural
// one (each node's complementarity scaled by its bulk stiffness, not by the method's
// parameter), so a full step whose only fault is a node it leaves penetrating (the next test
// puts that node on the wall) is taken whatever the augmentation, on a linear and on a
// nonlinear bulk; a step that raises the residual more than tenfold over the recent iterates is
// shortened until it does not. A scripted bulk whose residual is the Newton step's linear model
// makes the full step exact for the system the step linearized.
#include "along_step_bulk.hpp"
#include "solver/contact_newton.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace sig
