// The globalization of the contact Newton driver (solver/newton_guard.hpp, contact_newton.hpp):
// its bookkeeping alone (the relaxed reference, Armijo's test, the cycle test), a problem whose
// full Newton steps cycle and that the guard solves, steps that lower the residual at every
// monotone iteration, and a body whose load no contact holds, named a drift.
#include "core/error.hpp"
#include "solver/condensed_bulk.hpp"
#include "solver/contact_newton.hpp"
#include "solver/newton_guard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

namespace sig {
namespace {

TEST(NewtonGuard, TheReferenceIsTheLargestOfTheWindow) {
  MeritMemory memory(3);
  for (double r : {5.0, 1.0, 2.0})
    memory.push(r);
  EXPECT_EQ(memory.reference(), 5.0);
  memory.push(0.5); // 5 leaves the window
  EXPECT_EQ(memory.reference(), 2.0);
  EXPECT_THROW(MeritMemory(0), Error);
}

TEST(NewtonGuard, DampingGrowsOnStallsAndFadesAfterAnyOtherStep) {
  // Levenberg-Marquardt's schedule: a short step that keeps most of the merit (a near-singular
  // tangent) damps from tau and tenfold more while they go on; any other step cuts it tenfold,
  // to none below tau. A short step that lowers the merit well, or a full one that barely does
  // (a slow contraction), is no stall.
  Damping damping;
  EXPECT_EQ(damping.factor(), 0.0);
  damping.after_step(1.0 / 64, 0.999);
  EXPECT_EQ(damping.factor(), Damping::kFirst);
  damping.after_step(1.0 / 64, 0.95);
  EXPECT_DOUBLE_EQ(damping.factor(), 10 * Damping::kFirst);
  damping.after_step(1.0 / 16, 0.3); // short but a real fall
  EXPECT_DOUBLE_EQ(damping.factor(), Damping::kFirst);
  damping.after_step(1.0, 0.95); // full, slow
  EXPECT_EQ(damping.factor(), 0.0);
  damping.after_step(0.125, 0.99); // not shorter than kShortStep
  EXPECT_EQ(damping.factor(), 0.0);
}

TEST(NewtonGuard, ArmijoAsksForTheSlopesFraction) {
  // ||R_trial||^2 <= ref^2 - 2 sigma alpha ||R||^2: at ref = ||R|| = 1 and alpha = 1 the trial
  // must be below sqrt(1 - 2e-4).
  EXPECT_TRUE(sufficient_decrease(std::sqrt(1 - 2 * kArmijo) - 1e-12, 1, 1, 1));
  EXPECT_FALSE(sufficient_decrease(std::sqrt(1 - 2 * kArmijo) + 1e-12, 1, 1, 1));
  EXPECT_TRUE(sufficient_decrease(1.0, 2.0, 1.0, 1.0)); // a relaxed reference allows a rise
}

TEST(NewtonGuard, ARateRepaysWhenKWatchStepsMoreAtItReachArmijo) {
  // Halving: kWatchSteps more halvings take 1 to 2^-kWatchSteps, which repays a start just above
  // it and not one at it (Armijo asks for a little less); no rate that does not fall, none from a
  // merit of 0.
  const double reached = std::pow(0.5, kWatchSteps);
  EXPECT_TRUE(rate_repays(1.0, 2.0, 1.001 * reached));
  EXPECT_FALSE(rate_repays(1.0, 2.0, reached));
  EXPECT_FALSE(rate_repays(1.0, 1.0, 1e6));
  EXPECT_FALSE(rate_repays(1.2, 1.0, 1e6));
  EXPECT_FALSE(rate_repays(1.0, 0.0, 1e6));
}

TEST(NewtonGuard, ARepeatWithoutProgressIsACycleButNotNewtonsOwnRepeat) {
  const KernelBranch on{true, false, 0}, off{false, false, 0};
  CycleGuard guard(10);
  EXPECT_FALSE(guard.repeats({on, off}, 1.0));
  EXPECT_FALSE(guard.repeats({on, off}, 1.0)); // the last iteration's set again: a period of 1
  EXPECT_FALSE(guard.repeats({off, on}, 1.2));
  EXPECT_TRUE(guard.repeats({on, off}, 1.1)); // period 2, no merit below 1 since
  CycleGuard progressing(10);
  EXPECT_FALSE(progressing.repeats({on, off}, 1.0));
  EXPECT_FALSE(progressing.repeats({off, on}, 0.5));
  EXPECT_FALSE(progressing.repeats({on, off}, 0.7)); // the merit fell to 0.5 in between
}

/// An LCP w <= 0, N >= 0, N w = 0, S w + N = f with S symmetric positive definite (found by a
/// random search): from this start full Newton-min steps (PDAS) visit the active sets 110, 010,
/// 001, 111 and return to 110, the cycling Ben Gharbia and Gilbert (Math. Program. 134, 2012)
/// show possible on P-matrices.
CondensedProblem cycling_lcp() {
  CondensedProblem p;
  p.S.resize(3, 3);
  p.S << 2.9864984000277666, -1.5384781356428876, 3.5708898623771281, -1.5384781356428876,
      1.0768284962604333, -1.6804869526854367, 3.5708898623771281, -1.6804869526854367,
      4.5707794370158901;
  p.f = Eigen::Vector3d(-1.5813146903607842, 1.4741471255648386, -0.38714783451161106);
  p.normal_dof = {0, 1, 2};
  p.gap = Eigen::VectorXd::Zero(3);
  return p;
}

ContactNewtonResult solve(const CondensedProblem& p, const Eigen::VectorXd& start, bool globalize,
                          Eigen::VectorXd* w = nullptr) {
  ContactSetting setting;
  setting.law.assign(p.normal_dof.size(), ContactLaw{});
  setting.weight = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(p.normal_dof.size()));
  ContactSolverParameters parameters;
  parameters.gamma = 1;
  const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
  ContactNewtonOptions options;
  options.eps = 1e-12;
  options.max_iterations = 50;
  options.globalize = globalize;
  CondensedBulk bulk(p, {}, start);
  ContactIterate iterate;
  ContactNewtonResult r = solve_contact(bulk, setting, *method, options, iterate);
  if (w) *w = bulk.displacement();
  return r;
}

TEST(NewtonGuard, ARewoundCondensedBulkIsAtItsCheckpoint) {
  // The watchdog's return on a linear bulk: rewind() restores the iterate and S w together (the
  // residual reads S w), so penetrations and residual are the checkpoint's bit for bit after two
  // accepted steps beyond it, and a half step from there ends where the first one did.
  CondensedBulk bulk(cycling_lcp(), {}, Eigen::Vector3d(0.1, -0.2, 0.3));
  const std::vector<NodeConditions> free(3);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3);
  const auto accept = [&](double alpha) {
    bulk.solve(free, none);
    EXPECT_TRUE(bulk.move(alpha));
    bulk.keep();
    bulk.restore();
    return std::pair{Eigen::VectorXd(bulk.penetration()), bulk.equilibrium_residual(none, none)};
  };
  accept(0.5);
  bulk.checkpoint();
  const auto at_checkpoint =
      std::pair{Eigen::VectorXd(bulk.penetration()), bulk.equilibrium_residual(none, none)};
  const auto one_step = accept(0.5);
  accept(0.25);
  ASSERT_NE(bulk.equilibrium_residual(none, none), at_checkpoint.second);
  bulk.rewind();
  EXPECT_EQ(bulk.penetration(), at_checkpoint.first);
  EXPECT_EQ(bulk.equilibrium_residual(none, none), at_checkpoint.second);
  EXPECT_EQ(accept(0.5), one_step);
}

TEST(NewtonGuard, FullStepsCycleAndTheGuardConverges) {
  const CondensedProblem p = cycling_lcp();
  const Eigen::Vector3d start(0.48928141441003098, 1.2306882818271245, -1.3389344676934845);
  const ContactNewtonResult full = solve(p, start, false);
  EXPECT_FALSE(full.converged);
  EXPECT_EQ(full.reason, NewtonFailure::cycling) << full.failure;
  Eigen::VectorXd w;
  const ContactNewtonResult guarded = solve(p, start, true, &w);
  ASSERT_TRUE(guarded.converged) << guarded.failure;
  // The complementarity solution: w <= 0, N >= 0, N w = 0, S w + N = f.
  EXPECT_LT((p.S * w + guarded.normal_force - p.f).norm(), 1e-12);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE(w[i], 1e-14);
    EXPECT_GE(guarded.normal_force[i], -1e-14);
    EXPECT_LT(std::abs(w[i] * guarded.normal_force[i]), 1e-14);
  }
  static_assert(kWatchSteps >= 4, "a shorter watch returns before the cycle is named");
  // After the cycle, one branch changes per iteration (Murty's rule). The cycle is named at its
  // fifth iteration (the active set 110 again), before the watchdog would return: its raise
  // (0.58 -> 10.4 at the second) has kWatchSteps = 4 steps to be repaid.
  EXPECT_EQ(guarded.history.back().kind, 3);
}

/// A random Coulomb problem on a symmetric positive definite bulk of m nodes (normal and
/// tangential unknowns), mu = 0.3, with a random start.
struct RandomCoulomb {
  CondensedProblem problem;
  ContactSetting setting;
  Eigen::VectorXd start;
};

RandomCoulomb random_coulomb(int m, std::mt19937& generator) {
  std::normal_distribution<double> normal;
  const int n = 2 * m;
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      A(i, j) = normal(generator);
  RandomCoulomb c;
  CondensedProblem& p = c.problem;
  p.S = A * A.transpose() + 0.05 * Eigen::MatrixXd::Identity(n, n);
  p.f.resize(n);
  for (int i = 0; i < n; ++i)
    p.f[i] = normal(generator);
  for (int i = 0; i < m; ++i) {
    p.normal_dof.push_back(i);
    p.tangential_dof.push_back(m + i);
  }
  p.gap = Eigen::VectorXd::Zero(m);
  c.start.resize(n);
  for (int i = 0; i < n; ++i)
    c.start[i] = normal(generator);
  c.setting.law.assign(m, ContactLaw{});
  for (ContactLaw& law : c.setting.law) {
    law.friction = FrictionLaw::coulomb;
    law.mu = 0.3;
  }
  c.setting.weight = Eigen::VectorXd::Ones(m);
  return c;
}

TEST(NewtonGuard, EveryAcceptedStepLowersItsMerit) {
  // Random Coulomb problems: every searched step lowered its search's merit (the residual of
  // the system it linearized, or, monotone, the residual itself) but the escapes from a kink,
  // kEscapes + 1 in a row at most before the next restriction of the steps, which has as many
  // (two restrictions); a few of the 4000 take monotone steps, so the test sees both merits.
  // A step from an iterate at round-off (below kMeritPrecision and eps) is taken as it stands
  // (NEWTON.md item 8): it may raise the merit.
  std::mt19937 generator(11);
  int monotone_steps = 0, searched_steps = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    RandomCoulomb c = random_coulomb(4 + trial % 5, generator);
    ContactSolverParameters parameters;
    parameters.gamma = std::pow(10.0, trial % 5 - 2);
    const std::unique_ptr<ContactMethod> method = make_contact_method(parameters);
    ContactNewtonOptions options;
    options.eps = 1e-10;
    CondensedBulk bulk(c.problem, {}, c.start);
    ContactIterate iterate;
    const ContactNewtonResult r = solve_contact(bulk, c.setting, *method, options, iterate);
    int escapes = 0;
    for (std::size_t k = 0; k < r.history.size(); ++k) {
      const IterationRecord& h = r.history[k];
      escapes = h.kind == 4 ? escapes + 1 : 0;
      EXPECT_LE(escapes, 2 * (kEscapes + 1)) << "trial " << trial;
      if (k > 0 && r.history[k - 1].residual <= kMeritPrecision) continue;
      if (h.kind == 0 || h.kind == 2 || h.kind == 3 || h.kind == 5) {
        ++searched_steps;
        EXPECT_LT(h.merit_ratio, 1.0) << "trial " << trial << " iteration " << k + 1;
      }
      if (h.kind == 2 && k > 0) {
        ++monotone_steps;
        EXPECT_LT(h.residual, r.history[k - 1].residual) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(monotone_steps, 0) << "the sample took no monotone step: it tests nothing";
  EXPECT_GT(searched_steps, 10000);
}

TEST(NewtonGuard, EveryFrictionlessProblemConverges) {
  // Signorini on a symmetric positive definite bulk is a P-matrix LCP: block changes of the
  // active set may cycle (FullStepsCycleAndTheGuardConverges), Murty's single changes do not.
  std::mt19937 generator(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 2000; ++trial) {
    const int m = 3 + trial % 4;
    Eigen::MatrixXd A(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        A(i, j) = normal(generator);
    CondensedProblem p;
    p.S = A * A.transpose() + 0.05 * Eigen::MatrixXd::Identity(m, m);
    p.f.resize(m);
    Eigen::VectorXd start(m);
    for (int i = 0; i < m; ++i) {
      p.f[i] = normal(generator);
      start[i] = normal(generator);
      p.normal_dof.push_back(i);
    }
    p.gap = Eigen::VectorXd::Zero(m);
    const ContactNewtonResult r = solve(p, start, true);
    EXPECT_TRUE(r.converged) << "trial " << trial << ": " << r.failure;
  }
}

TEST(NewtonGuard, ALoadNoContactHoldsIsADrift) {
  // One free dof (S = 0 but for the proximal term) pressed away from its obstacle: no contact
  // can hold it, the Newton step is unheld and nothing along it holds the body.
  CondensedProblem p;
  p.S = Eigen::MatrixXd::Zero(1, 1);
  p.f = Eigen::VectorXd::Constant(1, -1.0); // pulls w_n < 0: away from the obstacle
  p.normal_dof = {0};
  p.gap = Eigen::VectorXd::Zero(1);
  p.regularization = 1e-10;
  const ContactNewtonResult r = solve(p, Eigen::VectorXd::Zero(1), true);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.reason, NewtonFailure::drift) << r.failure;
  EXPECT_GT(r.drift, 1e6); // the load over the proximal term
}

} // namespace
} // namespace sig
