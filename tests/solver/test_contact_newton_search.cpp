// The line search of a nonlinear bulk (contact_newton.hpp): its merit holds the branches of the
// iteration's test, so a full Newton step whose only fault is a node it leaves penetrating while
// off the wall (the next test puts that node on the wall) is taken whatever the augmentation r,
// and the step length does not depend on the method's parameter. A scripted bulk whose residual
// is the Newton step's linear model makes the full step exact for the held system.
#include "along_step_bulk.hpp"
#include "solver/contact_newton.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace sig {
namespace {

/// Two contact nodes: node 0 on the obstacle surface (tested on the wall), node 1 off it by
/// 0.01, which the step moves by +0.02 (penetrating 0.01 at the full step). The equilibrium
/// residual falls linearly to 0 along the step: alpha = 1 solves the held system exactly.
class OvershootingBulk final : public test::AlongStepBulk {
public:
  Eigen::VectorXd penetration() const override {
    return Eigen::Vector2d(0.0, -0.01 + 0.02 * alpha_);
  }
  double equilibrium_residual(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return 1.0 - alpha_;
  }
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd&) override {
    EXPECT_TRUE(conditions[0].normal.imposed);
    EXPECT_FALSE(conditions[1].normal.imposed);
    StepSolution s;
    s.normal_increment = Eigen::Vector2d(0.0, 0.02);
    s.normal_force = Eigen::Vector2d(1.0, 0.0); // node 0's reaction
    s.tangential_force = Eigen::VectorXd::Zero(2);
    return s;
  }
};

double first_step_length(const std::string& method, double parameter, bool nonlinear) {
  OvershootingBulk bulk;
  bulk.is_nonlinear = nonlinear;
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
  options.line_search = true;
  ContactIterate iterate;
  const ContactNewtonResult r = solve_contact(bulk, setting, *m, options, iterate);
  EXPECT_EQ(r.step_length.size(), 1u);
  return r.step_length.empty() ? 0.0 : r.step_length[0];
}

TEST(ContactNewtonSearch, ANonlinearBulkTakesTheFullStepWhateverTheAugmentation) {
  // Measured on the trial's own branches, node 1's penetration would count r x 0.01 >= 1, the
  // whole starting residual, for r >= 100, and the search would halve the step.
  for (const char* method : {"pdas", "alm", "projection"})
    for (double r : {1.0, 1e2, 1e4, 1e6})
      EXPECT_EQ(first_step_length(method, r, true), 1.0) << method << " r " << r;
}

TEST(ContactNewtonSearch, ALinearBulkStillDampsTheBranchChange) {
  // A linear bulk's search is there to damp branch changes: it keeps the trial's own branches,
  // so at r = 1e4 the full step that drives node 1 into the obstacle is halved.
  EXPECT_EQ(first_step_length("pdas", 1e4, false), 0.5);
}

} // namespace
} // namespace sig
