#pragma once
// The four contact methods (one file each in src/) and the small pieces their loops share.
#include "solver/contact_solver.hpp"

namespace sig {

class AugmentedLagrangian final : public ContactSolver {
public:
  explicit AugmentedLagrangian(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "alm"; }

private:
  ContactSolverParameters p_;
};

class Penalty final : public ContactSolver {
public:
  explicit Penalty(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "penalty"; }

private:
  ContactSolverParameters p_;
};

class PrimalDualActiveSet final : public ContactSolver {
public:
  explicit PrimalDualActiveSet(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "pdas"; }

private:
  ContactSolverParameters p_;
};

class IterativeProjection final : public ContactSolver {
public:
  explicit IterativeProjection(ContactSolverParameters p) : p_(std::move(p)) {}
  ContactSolution solve(const ContactProblem& problem) const override;
  std::string name() const override { return "projection"; }

private:
  ContactSolverParameters p_;
};

/// x = (u, lambda), the Newton vector of test (iv).
Eigen::VectorXd stack(const Eigen::VectorXd& u, const Eigen::VectorXd& lambda);
int count_active(const std::vector<char>& active);

} // namespace sig
