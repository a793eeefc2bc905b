// The four contact methods against an independent reference: the linear complementarity problem
// in the multipliers solved by projected Gauss-Seidel.
#include "core/error.hpp"
#include "solver/contact_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

namespace {

using sig::ContactProblem;
using sig::ContactSolverParameters;

/// A chain of n masses on springs (a 1D elastic bar), fixed or free at the left end, pushed by a
/// load onto obstacles in front of every node of its right half.
ContactProblem bar_problem(int n, bool clamped) {
  ContactProblem problem;
  problem.K = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e + 1 < n; ++e) {
    const double k = 1.0 + 0.1 * e;
    problem.K(e, e) += k;
    problem.K(e + 1, e + 1) += k;
    problem.K(e, e + 1) -= k;
    problem.K(e + 1, e) -= k;
  }
  if (clamped) problem.K(0, 0) += 10;
  problem.f = Eigen::VectorXd::Constant(n, 0.3);
  for (int i = n / 2; i < n; ++i)
    problem.normal_dof.push_back(i);
  problem.gap.resize(problem.contacts());
  for (int p = 0; p < problem.contacts(); ++p)
    problem.gap[p] = (p % 3 == 1) ? 50.0 : 0.1 + 0.05 * p;
  // Unequal nodal weights, so that pressures and forces differ.
  problem.weight = Eigen::VectorXd::LinSpaced(problem.contacts(), 0.5, 1.5);
  return problem;
}

/// Reference multipliers: W lambda + u_free <= g, lambda >= 0, complementarity, by projected
/// Gauss-Seidel on W = E K^-1 E^T (K must be nonsingular here).
Eigen::VectorXd reference_multipliers(const ContactProblem& problem) {
  const int m = problem.contacts();
  Eigen::LLT<Eigen::MatrixXd> K(problem.K);
  Eigen::MatrixXd Et = Eigen::MatrixXd::Zero(problem.size(), m);
  for (int p = 0; p < m; ++p)
    Et(problem.normal_dof[p], p) = 1;
  const Eigen::MatrixXd W = Et.transpose() * K.solve(Et);
  const Eigen::VectorXd un_free = Et.transpose() * K.solve(problem.f);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  for (int sweep = 0; sweep < 20000; ++sweep)
    for (int p = 0; p < m; ++p) {
      // u_n,p = un_free_p - (W lambda)_p <= g_p
      const double rest = un_free[p] - W.row(p).dot(lambda) + W(p, p) * lambda[p];
      lambda[p] = std::max(0.0, (rest - problem.gap[p]) / W(p, p));
    }
  return lambda;
}

void expect_signorini(const ContactProblem& problem, const sig::ContactSolution& s, double tol) {
  const Eigen::VectorXd un = problem.normal_part(s.u);
  for (int p = 0; p < problem.contacts(); ++p) {
    EXPECT_LE(un[p] - problem.gap[p], tol) << "penetration at element " << p;
    EXPECT_GE(s.multiplier[p], -tol) << "tension at element " << p;
    EXPECT_NEAR(s.multiplier[p] * (un[p] - problem.gap[p]), 0.0, tol) << "element " << p;
  }
  EXPECT_LT(sig::equilibrium_residual(problem, s.u, s.multiplier), 1e-8);
}

class EveryMethod : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryMethod, MatchesTheComplementarityReference) {
  const ContactProblem problem = bar_problem(12, true);
  const Eigen::VectorXd reference = reference_multipliers(problem);
  ASSERT_GT(reference.maxCoeff(), 0.1) << "the test needs some contact";
  ASSERT_EQ((reference.array() == 0).count() > 0, true) << "and some nodes out of contact";

  ContactSolverParameters parameters;
  parameters.method = GetParam();
  const bool penalty = parameters.method == std::string("penalty");
  // Penalty's residual has a round-off floor of about r * 1e-16 * ||u||: a looser eps for it.
  parameters.r = penalty ? 1e6 : 10;
  parameters.eps = penalty ? 1e-9 : 1e-10;
  const sig::ContactSolution s = sig::make_contact_solver(parameters)->solve(problem);
  ASSERT_TRUE(s.converged) << s.failure;
  // Penalty penetrates by lambda / r: compare to that accuracy.
  const double tol = penalty ? 1e-5 : 1e-9;
  EXPECT_LT((s.multiplier - reference).norm(), tol * std::max(1.0, reference.norm()));
  expect_signorini(problem, s, penalty ? 1e-5 : 1e-10);
}

INSTANTIATE_TEST_SUITE_P(ContactMethods, EveryMethod,
                         ::testing::Values("alm", "penalty", "pdas", "projection"));

TEST(ContactMethods, AugmentedLagrangianCarriesOneMultiplierUnknownPerElement) {
  const ContactProblem problem = bar_problem(12, true);
  ContactSolverParameters parameters;
  parameters.method = "alm";
  const auto s = sig::make_contact_solver(parameters)->solve(problem);
  EXPECT_EQ(s.unknowns, problem.size() + problem.contacts());
  parameters.method = "pdas";
  EXPECT_EQ(sig::make_contact_solver(parameters)->solve(problem).unknowns, problem.size());
}

TEST(ContactMethods, SemiCoerciveProblemIsSolvedThroughTheVanishingRegularization) {
  // A free bar: K is singular (translation), only contact holds it. The proximal term makes each
  // step well posed and leaves no trace in the converged state.
  ContactProblem problem = bar_problem(10, false);
  problem.regularization = 1e-10;
  for (const char* method : {"alm", "pdas", "projection"}) {
    ContactSolverParameters parameters;
    parameters.method = method;
    parameters.eps = 1e-10;
    parameters.c = 10;
    const auto s = sig::make_contact_solver(parameters)->solve(problem);
    ASSERT_TRUE(s.converged) << method << ": " << s.failure;
    expect_signorini(problem, s, 1e-8);
    // Total load is carried by the contact forces alone.
    EXPECT_NEAR(s.multiplier.sum(), problem.f.sum(), 1e-8 * problem.f.sum()) << method;
  }
}

TEST(ContactMethods, ProjectionNeedsMoreIterationsForSmallC) {
  const ContactProblem problem = bar_problem(12, true);
  ContactSolverParameters parameters;
  parameters.method = "projection";
  parameters.c = 1e4;
  const int large_c = sig::make_contact_solver(parameters)->solve(problem).iterations();
  parameters.c = 0.1;
  const auto s = sig::make_contact_solver(parameters)->solve(problem);
  EXPECT_TRUE(s.converged) << s.failure;
  EXPECT_GT(s.iterations(), large_c + 3);
}

TEST(ContactMethods, PrimalDualActiveSetDoesNotDependOnGamma) {
  // With x(0) = 0 the active-set test reduces to lambda >= 0 on A and u_n >= g on I (Table 7.2).
  const ContactProblem problem = bar_problem(12, true);
  ContactSolverParameters parameters;
  parameters.method = "pdas";
  std::vector<int> counts;
  for (double gamma : {1.0, 1e2, 1e4}) {
    parameters.gamma = gamma;
    counts.push_back(sig::make_contact_solver(parameters)->solve(problem).iterations());
  }
  EXPECT_EQ(counts[0], counts[1]);
  EXPECT_EQ(counts[1], counts[2]);
}

TEST(ContactMethods, NonConvergenceIsReportedNotHidden) {
  const ContactProblem problem = bar_problem(12, true);
  ContactSolverParameters parameters;
  parameters.method = "projection";
  parameters.c = 1e-3;
  parameters.max_iterations = 3;
  const auto s = sig::make_contact_solver(parameters)->solve(problem);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations(), 3);
  EXPECT_FALSE(s.failure.empty());
}

TEST(ContactMethods, UnknownMethodIsAnError) {
  ContactSolverParameters parameters;
  parameters.method = "newton";
  EXPECT_THROW(sig::make_contact_solver(parameters), sig::Error);
}

} // namespace
