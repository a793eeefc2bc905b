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

} // namespace
} // namespace sig
