#pragma once
// A scripted ContactBulk for the tests of the Newton driver's step (contact_newton.hpp): two
// frictionless contact nodes, and a state that is only the length alpha taken along the step, so
// that a test scripts the penetration, the residual and the step as functions of alpha.
#include "solver/contact_newton.hpp"

namespace sig::test {

class AlongStepBulk : public ContactBulk {
public:
  bool is_nonlinear = false;

  int contacts() const override { return 2; }
  bool has_tangential() const override { return false; }
  Eigen::VectorXd slip() const override { return Eigen::VectorXd::Zero(2); }
  double force_scale() const override { return 1; }
  Eigen::VectorXd contact_stiffness() const override { return Eigen::VectorXd::Ones(2); }
  bool move(double alpha) override {
    alpha_ = alpha;
    return true;
  }
  void keep() override { kept_ = alpha_; }
  void restore() override { alpha_ = kept_; }
  void checkpoint() override { checkpoint_ = alpha_; }
  void rewind() override { alpha_ = checkpoint_; }
  double displacement_norm() const override { return 1; }
  double displacement_step() const override { return alpha_; }
  bool nonlinear() const override { return is_nonlinear; }

protected:
  double alpha_ = 0, kept_ = 0, checkpoint_ = 0;
};

} // namespace sig::test
