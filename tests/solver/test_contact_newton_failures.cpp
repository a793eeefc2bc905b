// The driver where a step fails: a scripted bulk whose linear solve throws, or whose residual is
// not finite along part of the step. The driver must report the failure with the statuses of the
// last test (the writers index them per node), and never take a step of non-finite residual.
#include "along_step_bulk.hpp"
#include "core/error.hpp"
#include "solver/contact_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sig {
namespace {

/// Two contact nodes penetrating by 1, whose multiplier rows the step leaves as they are: the
/// residual's change along the step is `residual_at(alpha)`, alpha the step length of the move.
class ScriptedBulk final : public test::AlongStepBulk {
public:
  bool throw_on_solve = false;
  double (*residual_at)(double alpha) = [](double alpha) { return 1.0 - 0.5 * alpha; };

  Eigen::VectorXd penetration() const override { return Eigen::VectorXd::Ones(2); }
  double equilibrium_residual(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return residual_at(alpha_);
  }
  StepSolution solve(const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd&) override {
    if (throw_on_solve) SIG_VERIFY(false, "scripted: singular step matrix");
    EXPECT_EQ(conditions.size(), 2u);
    StepSolution s;
    s.normal_increment = Eigen::VectorXd::Constant(2, -1);
    s.normal_force = Eigen::VectorXd::Zero(2);
    s.tangential_force = Eigen::VectorXd::Zero(2);
    return s;
  }
};

ContactSetting two_signorini_nodes() {
  ContactSetting s;
  s.law.assign(2, ContactLaw{});
  s.weight = Eigen::VectorXd::Ones(2);
  return s;
}

ContactNewtonResult run(ScriptedBulk& bulk, int max_iterations = 1) {
  ContactSolverParameters parameters;
  const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
  ContactNewtonOptions options;
  options.max_iterations = max_iterations;
  ContactIterate iterate;
  return solve_contact(bulk, two_signorini_nodes(), *method, options, iterate);
}

TEST(ContactNewtonFailures, AFailedFirstSolveStillReportsEveryNodesStatus) {
  ScriptedBulk bulk;
  bulk.throw_on_solve = true;
  const ContactNewtonResult r = run(bulk);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.failure.find("could not be factorized"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("2 nodes on the wall"), std::string::npos) << r.failure;
  ASSERT_EQ(r.normal_status.size(), 2u);
  ASSERT_EQ(r.friction_status.size(), 2u);
  EXPECT_EQ(r.normal_status[0], NormalStatus::unilateral); // penetrating: tested on the wall
  EXPECT_EQ(r.friction_status[1], FrictionStatus::none);
  EXPECT_EQ(r.normal_force.size(), 2);
  EXPECT_TRUE(r.history.empty());
}

TEST(ContactNewtonFailures, ASearchNeverTakesANonFiniteResidual) {
  ScriptedBulk bulk;
  bulk.is_nonlinear = true;
  // No step length lowers ||R||: the search falls back on the largest admissible one, which
  // a NaN is not.
  bulk.residual_at = [](double alpha) {
    return alpha > 0.75 ? std::numeric_limits<double>::quiet_NaN() : 1.0 + 3 * alpha;
  };
  const ContactNewtonResult r = run(bulk);
  ASSERT_EQ(r.step_length.size(), 1u);
  ASSERT_EQ(r.history.size(), 1u);
  EXPECT_EQ(r.step_length[0], 0.5) << r.history[0].residual;
  EXPECT_TRUE(std::isfinite(r.history[0].residual));
}

TEST(ContactNewtonFailures, AFullStepOfNonFiniteResidualIsAFailureNotAResult) {
  ScriptedBulk bulk; // linear, no search: the full step is the only trial
  bulk.residual_at = [](double alpha) {
    return alpha > 0 ? std::numeric_limits<double>::infinity() : 1.0;
  };
  const ContactNewtonResult r = run(bulk, 5);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.failure.find("not finite"), std::string::npos) << r.failure;
  EXPECT_TRUE(r.history.empty());
  EXPECT_EQ(r.normal_status.size(), 2u);
}

} // namespace
} // namespace sig
