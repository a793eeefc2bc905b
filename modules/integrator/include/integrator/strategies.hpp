#pragma once
// The five strategies of contact_strategy.hpp (one file each in src/) and the pieces they share.
#include "integrator/bounded_newton.hpp"
#include "integrator/contact_strategy.hpp"
#include "solver/contact_method.hpp"

#include <vector>

namespace sig {

class SignoriniStrategy final : public ContactStrategy {
public:
  explicit SignoriniStrategy(ContactStrategyParameters p) : p_(p) {}
  ContactStepSolution solve(const NormalStep& step, const ContactBoundary& boundary) const override;
  std::string name() const override { return "signorini"; }

private:
  ContactStrategyParameters p_;
};

class ComplianceStrategy final : public ContactStrategy {
public:
  explicit ComplianceStrategy(ContactStrategyParameters p) : p_(p) {}
  ContactStepSolution solve(const NormalStep& step, const ContactBoundary& boundary) const override;
  std::string name() const override { return "compliance"; }

private:
  ContactStrategyParameters p_;
};

class SpecificPenaltyStrategy final : public ContactStrategy {
public:
  explicit SpecificPenaltyStrategy(ContactStrategyParameters p) : p_(p) {}
  ContactStepSolution solve(const NormalStep& step, const ContactBoundary& boundary) const override;
  std::string name() const override { return "specific-penalty"; }

private:
  ContactStrategyParameters p_;
};

class TwoStepStrategy final : public ContactStrategy {
public:
  explicit TwoStepStrategy(ContactStrategyParameters p) : p_(p) {}
  ContactStepSolution solve(const NormalStep& step, const ContactBoundary& boundary) const override;
  std::string name() const override { return "two-step"; }

private:
  ContactStrategyParameters p_;
};

class ImprovedPenaltyStrategy final : public ContactStrategy {
public:
  explicit ImprovedPenaltyStrategy(ContactStrategyParameters p) : p_(p) {}
  ContactStepSolution solve(const NormalStep& step, const ContactBoundary& boundary) const override;
  std::string name() const override { return "ipm"; }

private:
  ContactStrategyParameters p_;
};

/// A static contact method (solver/contact_method.hpp) on the condensed step restricted to the
/// contact elements `elements` (indices into the boundary), with bounds u_n <= gap on them; the
/// other nodes carry no force. Returns lambda on all p nodes (0 off `elements`), the static
/// method's convergence, failure and iteration count, and its final statuses on `active`.
ContactStepSolution solve_with_static_method(const NormalStep& step,
                                             const ContactBoundary& boundary,
                                             const std::vector<int>& elements,
                                             const Eigen::VectorXd& gap,
                                             const ContactSolverParameters& method,
                                             std::vector<char>* active = nullptr);

/// solve_with_static_method on every contact element, with bounds u_n <= gap; lambda = 0 at once
/// when the free step x_free stays within them (free flight: every condition holds).
ContactStepSolution solve_unilateral(const NormalStep& step, const ContactBoundary& boundary,
                                     const Eigen::VectorXd& gap,
                                     const ContactSolverParameters& method,
                                     std::vector<char>* active = nullptr);

/// The static method's parameters for a dynamic step: the strategy's iteration limit, and a
/// stopping test (iv) tight enough that the converged active set, solved exactly, is the answer.
ContactSolverParameters static_method(const std::string& method,
                                      const ContactStrategyParameters& p);

/// phi_i(x) = r w_i p(a_i, x_i - d_i) of (3.51), a_i = x_now,i - d_i
/// (specific_penalty_strategy.cpp).
NodalForceLaw specific_penalty_law(const ContactBoundary& boundary, const Eigen::VectorXd& x_now,
                                   double r);

/// True if some x_i exceeds limit_i (nothing to do for a unilateral law otherwise).
bool any_beyond(const Eigen::VectorXd& x, const Eigen::VectorXd& limit);

} // namespace sig
