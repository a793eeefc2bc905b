// The one contact Newton driver with the four methods on condensed linear bulks, against
// independent references: the linear complementarity problem of frictionless contact solved by
// projected Gauss-Seidel, frictional contact (Coulomb and Tresca) solved by a non-smooth
// Gauss-Seidel on the Delassus operator with an exact local solver, and the full generalized
// Newton step of the Alart-Curnier system (u, lambda, t) built densely from the kernel's
// derivatives (the driver eliminates the multiplier rows; the step must not change). Then the
// limits the laws must reach: mu = 0 is frictionless, an infinite Tresca threshold sticks
// everywhere and a zero one slips everywhere, compliance-unilateral is compliance for a deep wall
// and Signorini for g = 0.
#include "core/error.hpp"
#include "frictional_problem.hpp"
#include "solver/condensed_contact.hpp"
#include "solver/dense_cholesky.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <random>

namespace sig {
namespace {

using test::coulomb;
using test::Frictional;
using test::tresca;

// --- A frictionless bar, the LCP reference ----------------------------------------------------

/// A chain of n masses on springs (a 1D elastic bar), fixed or free at the left end, pushed by a
/// load onto obstacles in front of every node of its right half (normal unknowns only).
struct Bar {
  CondensedProblem problem;
  ContactSetting setting;
};

Bar bar_problem(int n, bool clamped) {
  Bar b;
  CondensedProblem& p = b.problem;
  p.S = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e + 1 < n; ++e) {
    const double k = 1.0 + 0.1 * e;
    p.S(e, e) += k;
    p.S(e + 1, e + 1) += k;
    p.S(e, e + 1) -= k;
    p.S(e + 1, e) -= k;
  }
  if (clamped) p.S(0, 0) += 10;
  p.f = Eigen::VectorXd::Constant(n, 0.3);
  for (int i = n / 2; i < n; ++i)
    p.normal_dof.push_back(i);
  const int m = static_cast<int>(p.normal_dof.size());
  p.gap.resize(m);
  for (int q = 0; q < m; ++q)
    p.gap[q] = (q % 3 == 1) ? 50.0 : 0.1 + 0.05 * q;
  // Unequal nodal weights, so that pressures and forces differ.
  b.setting.weight = Eigen::VectorXd::LinSpaced(m, 0.5, 1.5);
  b.setting.law.assign(m, ContactLaw{});
  return b;
}

/// Reference multipliers: W lambda + u_free <= g, lambda >= 0, complementarity, by projected
/// Gauss-Seidel on W = E K^-1 E^T (K must be nonsingular here).
Eigen::VectorXd reference_multipliers(const CondensedProblem& p) {
  const int m = static_cast<int>(p.normal_dof.size());
  const Eigen::LLT<Eigen::MatrixXd> K(p.S);
  Eigen::MatrixXd Et = Eigen::MatrixXd::Zero(p.f.size(), m);
  for (int q = 0; q < m; ++q)
    Et(p.normal_dof[q], q) = 1;
  const Eigen::MatrixXd W = Et.transpose() * K.solve(Et);
  const Eigen::VectorXd un_free = Et.transpose() * K.solve(p.f);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  for (int sweep = 0; sweep < 20000; ++sweep)
    for (int q = 0; q < m; ++q) {
      const double rest = un_free[q] - W.row(q).dot(lambda) + W(q, q) * lambda[q];
      lambda[q] = std::max(0.0, (rest - p.gap[q]) / W(q, q));
    }
  return lambda;
}

ContactSolverParameters parameters_for(const std::string& method, double eps = 1e-10) {
  ContactSolverParameters parameters;
  parameters.method = method;
  const bool penalty = method == "penalty";
  parameters.r = penalty ? 1e6 : 10;
  parameters.gamma = parameters.c = 10;
  // Penalty's residual has a round-off floor of about r * 1e-16 * ||u||: a looser eps for it.
  parameters.eps = penalty ? 1e-9 : eps;
  parameters.max_iterations = 100;
  return parameters;
}

void expect_signorini(const Bar& b, const CondensedSolution& s, double tol) {
  for (std::size_t q = 0; q < b.problem.normal_dof.size(); ++q) {
    const double gap = b.problem.gap[q] - s.w[b.problem.normal_dof[q]];
    const double force = s.contact.normal_force[q];
    EXPECT_GE(gap, -tol) << "penetration at element " << q;
    EXPECT_GE(force, -tol) << "tension at element " << q;
    // Complementarity as the natural residual min(force, gap): a node far from the obstacle
    // may keep a round-off force, a node in contact a round-off gap.
    EXPECT_LE(std::min(std::abs(force), std::abs(gap)), tol) << "element " << q;
  }
  Eigen::VectorXd r = b.problem.S * s.w - b.problem.f;
  for (std::size_t q = 0; q < b.problem.normal_dof.size(); ++q)
    r[b.problem.normal_dof[q]] += s.contact.normal_force[q];
  EXPECT_LT(r.norm(), 1e-8 * b.problem.f.norm());
}

class EveryMethod : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryMethod, MatchesTheComplementarityReference) {
  const Bar b = bar_problem(12, true);
  const Eigen::VectorXd reference = reference_multipliers(b.problem);
  ASSERT_GT(reference.maxCoeff(), 0.1) << "the test needs some contact";
  ASSERT_GT((reference.array() == 0).count(), 0) << "and some nodes out of contact";
  const ContactSolverParameters parameters = parameters_for(GetParam());
  const CondensedSolution s = solve_condensed_contact(b.problem, b.setting, parameters);
  ASSERT_TRUE(s.contact.converged) << s.contact.failure;
  // Penalty penetrates by lambda / r: compare to that accuracy.
  const bool penalty = parameters.method == "penalty";
  EXPECT_LT((s.contact.normal_force - reference).norm(),
            (penalty ? 1e-5 : 1e-9) * std::max(1.0, reference.norm()));
  expect_signorini(b, s, penalty ? 1e-5 : 1e-10);
  for (Eigen::Index q = 0; q < reference.size(); ++q)
    EXPECT_EQ(s.contact.normal_status[q] == NormalStatus::unilateral, reference[q] > 0) << q;
}

INSTANTIATE_TEST_SUITE_P(ContactMethods, EveryMethod,
                         ::testing::Values("alm", "penalty", "pdas", "projection"));

TEST(ContactMethods, AugmentedLagrangianCarriesOneMultiplierUnknownPerElement) {
  const Bar b = bar_problem(12, true);
  const int m = b.setting.size();
  EXPECT_EQ(
      solve_condensed_contact(b.problem, b.setting, parameters_for("alm")).multiplier_unknowns, m);
  EXPECT_EQ(
      solve_condensed_contact(b.problem, b.setting, parameters_for("pdas")).multiplier_unknowns, 0);
}

TEST(ContactMethods, SemiCoerciveProblemIsSolvedThroughTheVanishingRegularization) {
  // A free bar: K is singular (translation), only contact holds it. The proximal term makes each
  // step well posed and leaves no trace in the converged state.
  Bar b = bar_problem(10, false);
  b.problem.regularization = 1e-10;
  for (const char* method : {"alm", "pdas", "projection"}) {
    const CondensedSolution s =
        solve_condensed_contact(b.problem, b.setting, parameters_for(method));
    ASSERT_TRUE(s.contact.converged) << method << ": " << s.contact.failure;
    expect_signorini(b, s, 1e-8);
    // Total load is carried by the contact forces alone.
    EXPECT_NEAR(s.contact.normal_force.sum(), b.problem.f.sum(), 1e-8 * b.problem.f.sum())
        << method;
  }
}

TEST(ContactMethods, ProjectionNeedsMoreIterationsForSmallC) {
  const Bar b = bar_problem(12, true);
  ContactSolverParameters parameters = parameters_for("projection", 1e-5);
  parameters.c = 1e4;
  const int large_c =
      solve_condensed_contact(b.problem, b.setting, parameters).contact.iterations();
  parameters.c = 0.1;
  const CondensedSolution s = solve_condensed_contact(b.problem, b.setting, parameters);
  EXPECT_TRUE(s.contact.converged) << s.contact.failure;
  EXPECT_GT(s.contact.iterations(), large_c + 3);
}

TEST(ContactMethods, PrimalDualActiveSetDoesNotDependOnGamma) {
  // With x(0) = 0 the active-set test reduces to lambda >= 0 on A and u_n >= g on I (Table 7.2).
  const Bar b = bar_problem(12, true);
  std::vector<int> counts;
  for (double gamma : {1.0, 1e2, 1e4}) {
    ContactSolverParameters parameters = parameters_for("pdas", 1e-5);
    parameters.gamma = gamma;
    counts.push_back(
        solve_condensed_contact(b.problem, b.setting, parameters).contact.iterations());
  }
  EXPECT_EQ(counts[0], counts[1]);
  EXPECT_EQ(counts[1], counts[2]);
}

TEST(ContactMethods, NonConvergenceIsReportedNotHidden) {
  const Bar b = bar_problem(12, true);
  ContactSolverParameters parameters = parameters_for("projection");
  parameters.c = 1e-3;
  parameters.max_iterations = 3;
  const CondensedSolution s = solve_condensed_contact(b.problem, b.setting, parameters);
  EXPECT_FALSE(s.contact.converged);
  EXPECT_EQ(s.contact.iterations(), 3);
  EXPECT_FALSE(s.contact.failure.empty());
}

TEST(ContactMethods, UnknownMethodIsAnError) {
  ContactSolverParameters parameters;
  parameters.method = "newton";
  EXPECT_THROW(make_contact_method(parameters), Error);
}

// --- A frictional problem, the non-smooth Gauss-Seidel reference -------------------------------

/// m contact nodes with (w_t, w_n) each, a dense SPD S coupling all of them, a load pressing
/// them onto the obstacle and pushing them along +t (so that some stick and some slip), gaps
/// from 0 (touching) to out of reach.
Frictional frictional_problem(const ContactLaw& law, int m = 9) {
  return test::random_frictional_problem(
      2, m, 7, law, [](int c, double u) { return c == 0 ? 0.6 + 0.5 * u : 1.5 + 0.5 * u; });
}

/// The local problem of node q given the others' forces: find mu = (T, N) with q = c - W mu
/// obeying the law (nodal forces; the wall at q_n = depth). Every branch (free/contact x
/// stick/slip+/slip-) is a 2 x 2 linear problem; the one whose solution is admissible is taken.
Eigen::Vector2d local_solve(const Eigen::Matrix2d& W, const Eigen::Vector2d& c,
                            const ContactLaw& law, double weight) {
  for (int normal = 0; normal < 2; ++normal)
    for (int tangential = 0; tangential < 3; ++tangential) { // 0 stick, 1 slip+, 2 slip-
      // Unknowns mu = (T, N); rows: normal: N = 0 or q_n = depth; tangential: q_t = 0 or
      // T = sigma s with s = threshold w (tresca) or mu N (coulomb).
      const double sigma = tangential == 1 ? 1.0 : -1.0;
      Eigen::Matrix2d M;
      Eigen::Vector2d b;
      if (normal == 0) { // N = 0
        M.row(1) << 0, 1;
        b[1] = 0;
      } else { // c_n - W_n. mu = depth
        M.row(1) = W.row(1);
        b[1] = c[1] - law.depth;
      }
      if (tangential == 0) { // c_t - W_t. mu = 0
        M.row(0) = W.row(0);
        b[0] = c[0];
      } else if (law.friction == FrictionLaw::coulomb) {
        M.row(0) << 1, -sigma * law.mu;
        b[0] = 0;
      } else {
        M.row(0) << 1, 0;
        b[0] = sigma * law.threshold * weight;
      }
      const Eigen::Vector2d mu = M.partialPivLu().solve(b);
      const Eigen::Vector2d q = c - W * mu;
      const double s =
          law.friction == FrictionLaw::coulomb ? law.mu * mu[1] : law.threshold * weight;
      const double tol = 1e-13 * (1 + c.norm());
      const bool normal_ok = normal == 0 ? q[1] <= law.depth + tol : mu[1] >= -tol;
      const bool tangential_ok =
          tangential == 0 ? std::abs(mu[0]) <= s + tol : sigma * q[0] >= -tol;
      if (normal_ok && tangential_ok) return mu;
    }
  ADD_FAILURE() << "no admissible local branch";
  return Eigen::Vector2d::Zero();
}

/// Forces (T, N) per node by non-smooth Gauss-Seidel on the Delassus operator W = B S^-1 B^T.
Eigen::MatrixXd gauss_seidel_reference(const Frictional& fr) {
  const CondensedProblem& p = fr.problem;
  const int m = fr.setting.size();
  const Eigen::LLT<Eigen::MatrixXd> S(p.S);
  const Eigen::MatrixXd W = S.solve(Eigen::MatrixXd::Identity(2 * m, 2 * m)); // B = I here
  Eigen::VectorXd q_free = S.solve(p.f);
  for (int q = 0; q < m; ++q)
    q_free[2 * q + 1] -= p.gap[q];
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(2 * m); // (T, N) per node, like the unknowns
  for (int sweep = 0; sweep < 5000; ++sweep)
    for (int q = 0; q < m; ++q) {
      const Eigen::Matrix2d Wqq = W.block<2, 2>(2 * q, 2 * q);
      const Eigen::Vector2d c =
          q_free.segment<2>(2 * q) - W.middleRows<2>(2 * q) * mu + Wqq * mu.segment<2>(2 * q);
      mu.segment<2>(2 * q) = local_solve(Wqq, c, fr.setting.law[q], fr.setting.weight[q]);
    }
  Eigen::MatrixXd forces(m, 2);
  for (int q = 0; q < m; ++q)
    forces.row(q) = mu.segment<2>(2 * q).transpose();
  return forces;
}

class FrictionMethods : public ::testing::TestWithParam<const char*> {};

TEST_P(FrictionMethods, CoulombAndTrescaMatchTheGaussSeidelReference) {
  for (const ContactLaw& law : {coulomb(0.3), tresca(0.4)}) {
    const Frictional fr = frictional_problem(law);
    const Eigen::MatrixXd reference = gauss_seidel_reference(fr);
    const CondensedSolution s =
        solve_condensed_contact(fr.problem, fr.setting, parameters_for(GetParam()));
    ASSERT_TRUE(s.contact.converged)
        << GetParam() << " " << describe(law) << ": " << s.contact.failure;
    const bool penalty = std::string(GetParam()) == "penalty";
    const double tol = (penalty ? 1e-5 : 1e-9) * reference.cwiseAbs().maxCoeff();
    int stick = 0, slip = 0;
    for (int q = 0; q < fr.setting.size(); ++q) {
      EXPECT_NEAR(s.contact.tangential_force[q], reference(q, 0), tol) << describe(law) << " " << q;
      EXPECT_NEAR(s.contact.normal_force[q], reference(q, 1), tol) << describe(law) << " " << q;
      stick += s.contact.friction_status[q] == FrictionStatus::stick;
      slip += s.contact.friction_status[q] == FrictionStatus::slip_forward ||
              s.contact.friction_status[q] == FrictionStatus::slip_backward;
    }
    EXPECT_GT(stick, 0) << describe(law) << ": the test needs sticking nodes";
    EXPECT_GT(slip, 0) << describe(law) << ": and slipping ones";
  }
}

INSTANTIATE_TEST_SUITE_P(ContactMethods, FrictionMethods,
                         ::testing::Values("alm", "penalty", "pdas", "projection"));

// --- The eliminated step is the Alart-Curnier generalized Newton step --------------------------

/// One generalized Newton step on X = (w, lambda, t) (nodal-force multipliers) of
///   R_w = S w - f + sum_q w_q (N_q e_n + T_q e_t),  R_lambda = w C_n,  R_t = w C_t,
/// with the kernel's forces and derivatives, solved densely.
Eigen::VectorXd dense_alart_curnier_step(const Frictional& fr, const Eigen::VectorXd& X, double r) {
  const CondensedProblem& p = fr.problem;
  const int m = fr.setting.size(), n = static_cast<int>(p.f.size());
  Eigen::VectorXd R = Eigen::VectorXd::Zero(n + 2 * m);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 2 * m, n + 2 * m);
  R.head(n) = p.S * X.head(n) - p.f;
  J.topLeftCorner(n, n) = p.S;
  for (int q = 0; q < m; ++q) {
    const double w = fr.setting.weight[q];
    const int dn = p.normal_dof[q], dt = p.tangential_dof[q];
    const NodeVariables x{X[dn] - p.gap[q], X[dt], X[n + q] / w, X[n + m + q] / w};
    // The slip's augmentation capped at the node's natural scale (solver/contact_newton.hpp).
    const ContactKernel k = contact_kernel(fr.setting.law[q], x, r, std::min(r, p.S(dn, dn) / w));
    // d/d(w_n, w_t, lambda_nodal, t_nodal) = (d/dq_n, d/dq_t, d/dlambda / w, d/dt / w).
    const int column[4] = {dn, dt, n + q, n + m + q};
    const double scale[4] = {1.0, 1.0, 1.0 / w, 1.0 / w};
    R[dn] += w * k.normal;
    R[dt] += w * k.tangential;
    R[n + q] = w * k.complementarity[0];
    R[n + m + q] = w * k.complementarity[1];
    for (int j = 0; j < 4; ++j) {
      J(dn, column[j]) += w * k.d_force(0, j) * scale[j];
      J(dt, column[j]) += w * k.d_force(1, j) * scale[j];
      J(n + q, column[j]) = w * k.d_complementarity(0, j) * scale[j];
      J(n + m + q, column[j]) = w * k.d_complementarity(1, j) * scale[j];
    }
  }
  return X - J.fullPivLu().solve(R);
}

/// Compliance with a wall at g and Coulomb friction bounded by the compliance pressure only
/// (bound=compliance, (4.6)): Tresca's mu p(g) on the wall.
ContactLaw compliance_bounded(double mu) {
  ContactLaw law = coulomb(mu);
  law.normal = NormalLaw::compliance_unilateral;
  law.cn = 5;
  law.depth = 0.1;
  law.bound = FrictionBound::compliance;
  return law;
}

TEST(ContactNewton, TheStepIsTheAlartCurnierNewtonStep) {
  for (const ContactLaw& law : {coulomb(0.3), tresca(0.4), compliance_bounded(0.3)})
    for (const char* method : {"alm", "pdas"}) {
      const Frictional fr = frictional_problem(law);
      const int m = fr.setting.size(), n = static_cast<int>(fr.problem.f.size());
      // An iterate away from the solution: some nodes on the wall, some sticking, some slipping.
      std::mt19937 random(3);
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      Eigen::VectorXd X(n + 2 * m);
      for (int i = 0; i < n + 2 * m; ++i)
        X[i] = 0.3 * uniform(random) + (i >= n && i < n + m ? 0.4 : 0.0);
      const std::unique_ptr<ContactMethod> newton = make_contact_method(parameters_for(method));
      CondensedBulk bulk(fr.problem, {}, X.head(n));
      ContactIterate iterate{X.segment(n, m), X.tail(m), {}};
      const ContactNewtonResult c = solve_contact(bulk, fr.setting, *newton, {1e-12, 1}, iterate);
      ASSERT_EQ(c.iterations(), 1) << c.failure;
      ASSERT_GT(c.history[0].active, 0);
      ASSERT_LT(c.history[0].active, m);
      if (law.bound == FrictionBound::compliance) { // slips on the wall and off it, both
        int wall_slip = 0, slip = 0;
        for (const NodeBranch& b : iterate.branch) {
          wall_slip += b.wall && b.slip != 0;
          slip += !b.wall && b.slip != 0;
        }
        ASSERT_GT(wall_slip, 0) << method;
        ASSERT_GT(slip, 0) << method;
      }
      const Eigen::VectorXd expected = dense_alart_curnier_step(fr, X, newton->augmentation());
      const double tol = 1e-10 * expected.cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(bulk.displacement()[i], expected[i], tol) << method << " w " << i;
      for (int q = 0; q < m; ++q) {
        EXPECT_NEAR(iterate.lambda[q], expected[n + q], tol) << method << " lambda " << q;
        EXPECT_NEAR(iterate.t[q], expected[n + m + q], tol) << method << " t " << q;
      }
    }
}

// --- Limits of the laws --------------------------------------------------------------------------

/// The frictional problem condensed onto its normal unknowns (the frictionless path of
/// sig-solve), law `law` on every node.
Frictional frictionless_condensation(const Frictional& fr, const ContactLaw& law) {
  const CondensedProblem& p = fr.problem;
  const int m = fr.setting.size();
  Eigen::MatrixXd Snn(m, m), Snt(m, m), Stt(m, m);
  Eigen::VectorXd fn(m), ft(m);
  for (int a = 0; a < m; ++a) {
    fn[a] = p.f[p.normal_dof[a]];
    ft[a] = p.f[p.tangential_dof[a]];
    for (int b = 0; b < m; ++b) {
      Snn(a, b) = p.S(p.normal_dof[a], p.normal_dof[b]);
      Snt(a, b) = p.S(p.normal_dof[a], p.tangential_dof[b]);
      Stt(a, b) = p.S(p.tangential_dof[a], p.tangential_dof[b]);
    }
  }
  const Eigen::LLT<Eigen::MatrixXd> tt(Stt);
  Frictional c;
  c.problem.S = Snn - Snt * tt.solve(Snt.transpose());
  c.problem.f = fn - Snt * tt.solve(ft);
  c.problem.gap = p.gap;
  for (int a = 0; a < m; ++a)
    c.problem.normal_dof.push_back(a);
  c.setting = {std::vector<ContactLaw>(m, law), fr.setting.weight};
  return c;
}

TEST(ContactLaws, ZeroFrictionIsFrictionless) {
  const Frictional fr = frictional_problem(coulomb(0.0));
  const Frictional frictionless = frictionless_condensation(fr, ContactLaw{});
  for (const char* method : {"alm", "pdas", "projection", "penalty"}) {
    const CondensedSolution with =
        solve_condensed_contact(fr.problem, fr.setting, parameters_for(method));
    const CondensedSolution without =
        solve_condensed_contact(frictionless.problem, frictionless.setting, parameters_for(method));
    ASSERT_TRUE(with.contact.converged && without.contact.converged) << method;
    // Round-off: the two condensations order their operations differently, and penalty's stiff
    // springs (r = 1e6) amplify it to its residual floor.
    const double scale = without.contact.normal_force.cwiseAbs().maxCoeff();
    const double tol = std::string(method) == "penalty" ? 1e-9 : 1e-12;
    EXPECT_LT((with.contact.normal_force - without.contact.normal_force).cwiseAbs().maxCoeff(),
              tol * scale)
        << method;
    EXPECT_LT(with.contact.tangential_force.cwiseAbs().maxCoeff(), 1e-14 * scale) << method;
  }
}

TEST(ContactLaws, TrescaSticksEverywhereOrSlipsEverywhere) {
  for (const char* method : {"alm", "pdas", "projection"}) {
    const Frictional stuck = frictional_problem(tresca(1e12));
    const CondensedSolution s =
        solve_condensed_contact(stuck.problem, stuck.setting, parameters_for(method));
    ASSERT_TRUE(s.contact.converged) << method << ": " << s.contact.failure;
    for (int q = 0; q < stuck.setting.size(); ++q) {
      EXPECT_EQ(s.contact.friction_status[q], FrictionStatus::stick) << method << " " << q;
      EXPECT_LT(std::abs(s.w[stuck.problem.tangential_dof[q]]), 1e-12) << method << " " << q;
    }
    const Frictional slipping = frictional_problem(tresca(0.0));
    const CondensedSolution z =
        solve_condensed_contact(slipping.problem, slipping.setting, parameters_for(method));
    ASSERT_TRUE(z.contact.converged) << method << ": " << z.contact.failure;
    for (int q = 0; q < slipping.setting.size(); ++q) {
      EXPECT_TRUE(z.contact.friction_status[q] == FrictionStatus::slip_forward ||
                  z.contact.friction_status[q] == FrictionStatus::slip_backward)
          << method << " " << q;
      EXPECT_LT(std::abs(z.contact.tangential_force[q]),
                1e-14 * z.contact.normal_force.cwiseAbs().maxCoeff())
          << method << " " << q;
    }
  }
}

TEST(ContactLaws, UnilateralComplianceBetweenComplianceAndSignorini) {
  const Frictional base = frictional_problem(ContactLaw{});
  ContactLaw compliance;
  compliance.normal = NormalLaw::compliance;
  compliance.cn = 20;
  ContactLaw unilateral = compliance;
  unilateral.normal = NormalLaw::compliance_unilateral;
  for (const char* method : {"alm", "pdas", "projection"}) {
    const auto solve = [&](const ContactLaw& law) {
      const Frictional fr = frictionless_condensation(base, law);
      const CondensedSolution s =
          solve_condensed_contact(fr.problem, fr.setting, parameters_for(method));
      EXPECT_TRUE(s.contact.converged)
          << method << " " << describe(law) << ": " << s.contact.failure;
      return s;
    };
    // The same Newton steps for alm and pdas; projection's Robin relaxation acts on the nodes of
    // a law with a wall only, so its iterates differ and agree to the stopping tolerance.
    const double tol = std::string(method) == "projection" ? 1e-9 : 1e-12;
    unilateral.depth = 1e6; // the wall out of reach: pure compliance
    const CondensedSolution deep = solve(unilateral), pure = solve(compliance);
    const double scale = pure.contact.normal_force.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0);
    EXPECT_LT((deep.contact.normal_force - pure.contact.normal_force).cwiseAbs().maxCoeff(),
              tol * scale)
        << method;
    for (NormalStatus status : deep.contact.normal_status)
      EXPECT_NE(status, NormalStatus::unilateral) << method;
    unilateral.depth = 0; // the wall at the surface: Signorini
    const CondensedSolution flat = solve(unilateral), signorini = solve(ContactLaw{});
    EXPECT_LT((flat.contact.normal_force - signorini.contact.normal_force).cwiseAbs().maxCoeff(),
              1e-12 * signorini.contact.normal_force.cwiseAbs().maxCoeff())
        << method;
    EXPECT_EQ(flat.contact.normal_status, signorini.contact.normal_status) << method;
    // In between, both statuses: compliance (CN) and the wall (CU).
    unilateral.depth = 0.05;
    const std::vector<NormalStatus> between = solve(unilateral).contact.normal_status;
    EXPECT_GT(std::count(between.begin(), between.end(), NormalStatus::compliance), 0) << method;
    EXPECT_GT(std::count(between.begin(), between.end(), NormalStatus::unilateral), 0) << method;
    // Deeper walls, where full Newton steps cycle on the compliance kink: the default search
    // (search=auto) converges (solve() expects it).
    for (const double depth : {0.1, 0.2, 0.5}) {
      unilateral.depth = depth;
      solve(unilateral);
    }
  }
}

} // namespace
} // namespace sig

namespace sig {
namespace {

// --- The condensed bulk's step against a dense solve of the same linear step --------------------

/// The linear step of condensed_bulk.hpp written out densely: unknowns z (all n) and the contact
/// forces F of the contact dofs; (S z)_i + eps (z_i - w_i) + F_i = f_i, and per contact dof
/// either z = w + value or F = force + k (z - w) + coupling N_p + cross (z_n - w_n).
void dense_step(const CondensedProblem& p, const std::vector<NodeConditions>& conditions,
                const Eigen::VectorXd& w, Eigen::VectorXd& z, Eigen::VectorXd& N,
                Eigen::VectorXd& T) {
  const int n = static_cast<int>(p.f.size()), m = static_cast<int>(p.normal_dof.size());
  const int size = n + 2 * m; // z, then (N_p, T_p) per node
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd b(size);
  A.topLeftCorner(n, n) = p.S;
  A.topLeftCorner(n, n).diagonal().array() += p.regularization;
  b.head(n) = p.f + p.regularization * w;
  for (int q = 0; q < m; ++q) {
    const int dof[2] = {p.normal_dof[q], p.tangential_dof[q]};
    const DofCondition* c[2] = {&conditions[q].normal, &conditions[q].tangential};
    for (int k = 0; k < 2; ++k) {
      const int force = n + 2 * q + k, row = force;
      A(dof[k], force) = 1; // + F in the equilibrium row
      if (c[k]->imposed) {
        A(row, dof[k]) = 1;
        b[row] = w[dof[k]] + c[k]->value;
      } else { // F - k z - coupling N - cross z_n = force - k w - cross w_n
        A(row, force) = 1;
        A(row, dof[k]) -= c[k]->stiffness;
        b[row] = c[k]->force - c[k]->stiffness * w[dof[k]];
        if (k == 1) {
          A(row, n + 2 * q) -= c[k]->coupling;
          A(row, dof[0]) -= c[k]->cross;
          b[row] -= c[k]->cross * w[dof[0]];
        }
      }
    }
  }
  const Eigen::VectorXd x = A.fullPivLu().solve(b);
  z = x.head(n);
  N.resize(m);
  T.resize(m);
  for (int q = 0; q < m; ++q) {
    N[q] = x[n + 2 * q];
    T[q] = x[n + 2 * q + 1];
  }
}

/// Default conditions (springs k0) but on the nodes [first, last), which take the four kinds of
/// frictional conditions in turn: stick on the wall, Coulomb slip on it, slip on a compliance,
/// penalty stick.
std::vector<NodeConditions> mixed_zone(const Eigen::VectorXd& k0, int first, int last,
                                       std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<NodeConditions> conditions(k0.size());
  for (int q = 0; q < static_cast<int>(k0.size()); ++q) {
    conditions[q].normal.stiffness = k0[q];
    if (q < first || q >= last) continue;
    NodeConditions& c = conditions[q];
    switch (q % 4) {
    case 0: // on the wall, sticking
      c.normal = {true, 0.01 * uniform(random), 0, 0, 0, 0};
      c.tangential = {true, 0.01 * uniform(random), 0, 0, 0, 0};
      break;
    case 1: // on the wall, Coulomb slip
      c.normal = {true, 0.01 * uniform(random), 0, 0, 0, 0};
      c.tangential.coupling = 0.3;
      break;
    case 2: // compliance, Coulomb slip on it
      c.normal = {false, 0, 0.2, 1.5, 0, 0};
      c.tangential.force = -0.06;
      c.tangential.cross = -0.45;
      break;
    default: // penalty stick
      c.normal = {false, 0, 0.1, 2.0, 0, 0};
      c.tangential = {false, 0, 0.05, 3.0, 0, 0};
    }
  }
  return conditions;
}

TEST(CondensedBulk, EveryStepIsTheDenseStepWhateverTheTail) {
  // 40 nodes, ordered by decreasing gap (node q at place q); a contact zone that grows and
  // shrinks at the end of the order (the tail updated both ways), then jumps to its start (a
  // reorder puts it last) and moves on from there.
  const int m = 40;
  Frictional fr = frictional_problem(coulomb(0.3), m);
  fr.problem.regularization = 1e-3;
  for (int q = 0; q < m; ++q)
    fr.problem.gap[q] = 0.01 * (m - q);
  Eigen::VectorXd k0 = Eigen::VectorXd::Zero(m);
  for (int q = 0; q < m; q += 3)
    k0[q] = 0.7; // projection-like default springs on some nodes
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd w(2 * m);
  for (int i = 0; i < 2 * m; ++i)
    w[i] = 0.1 * uniform(random);
  CondensedBulk bulk(fr.problem, k0, w);
  const int zones[][2] = {{30, 40}, {28, 40}, {25, 40}, {27, 40}, {31, 40}, {0, 3},
                          {0, 4},   {0, 2},   {0, 40},  {20, 24}, {21, 24}, {18, 26}};
  for (const auto& zone : zones) {
    const std::vector<NodeConditions> conditions = mixed_zone(k0, zone[0], zone[1], random);
    Eigen::VectorXd z, N, T;
    dense_step(fr.problem, conditions, bulk.displacement(), z, N, T);
    const StepSolution s = bulk.solve(conditions, Eigen::VectorXd::Zero(m));
    ASSERT_TRUE(bulk.move(1.0));
    const double tol = 1e-10 * (1 + z.cwiseAbs().maxCoeff());
    for (int i = 0; i < 2 * m; ++i)
      ASSERT_NEAR(bulk.displacement()[i], z[i], tol) << "zone " << zone[0] << "-" << zone[1];
    for (int q = 0; q < m; ++q) {
      ASSERT_NEAR(s.normal_force[q], N[q], 1e-9 * (1 + N.cwiseAbs().maxCoeff())) << q;
      ASSERT_NEAR(s.tangential_force[q], T[q], 1e-9 * (1 + T.cwiseAbs().maxCoeff())) << q;
    }
  }
  EXPECT_GT(bulk.reorders(), 0) << "the sequence should make the bulk reorder";
}

/// The largest residual of the step equations (dense_step's) at z, N, T, relative to the
/// largest term: equilibrium (S + eps) z + F = f + eps w, and per component z = w + value where
/// imposed, F = force + k (z - w) + coupling N + cross (z_n - w_n) otherwise.
double step_residual(const CondensedProblem& p, const std::vector<NodeConditions>& conditions,
                     const Eigen::VectorXd& w, const Eigen::VectorXd& z, const Eigen::VectorXd& N,
                     const Eigen::VectorXd& T) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(z.size());
  double largest = (p.S * z).cwiseAbs().maxCoeff() + p.f.cwiseAbs().maxCoeff(), worst = 0;
  for (int q = 0; q < static_cast<int>(conditions.size()); ++q) {
    const int dof[2] = {p.normal_dof[q], p.tangential_dof[q]};
    const double force[2] = {N[q], T[q]};
    const DofCondition* c[2] = {&conditions[q].normal, &conditions[q].tangential};
    for (int k = 0; k < 2; ++k) {
      F[dof[k]] = force[k];
      const double dz = z[dof[k]] - w[dof[k]];
      worst =
          std::max(worst, c[k]->imposed ? std::abs(dz - c[k]->value)
                                        : std::abs(force[k] - c[k]->force - c[k]->stiffness * dz -
                                                   c[k]->coupling * N[q] -
                                                   c[k]->cross * (z[dof[0]] - w[dof[0]])));
    }
  }
  const Eigen::VectorXd equilibrium = p.S * z + p.regularization * (z - w) + F - p.f;
  return std::max(worst, equilibrium.cwiseAbs().maxCoeff()) / largest;
}

TEST(CondensedBulk, TailsOfBlasSizeSolveTheStep) {
  // 700 nodes (1400 unknowns): the tails from 1020 to 1400 unknowns take every way of forming
  // their Schur complement by BLAS (dense_cholesky.hpp's blas_min_rows = 1024): afresh as
  // L22 L22^T and as B_tail - L21 L21^T, longer and shorter than the last, one longer than a
  // tail formed below the threshold; and LAPACK's LU of the coupled systems.
  const int m = 700;
  ASSERT_LT(2 * (m - 190), blas_min_rows);
  Frictional fr = frictional_problem(coulomb(0.3), m);
  fr.problem.regularization = 1e-3;
  for (int q = 0; q < m; ++q)
    fr.problem.gap[q] = 0.01 * (m - q);
  const Eigen::VectorXd k0 = Eigen::VectorXd::Zero(m);
  CondensedBulk bulk(fr.problem, k0);
  std::mt19937 random(5);
  for (const int first : {176, 170, 180, 0, 100, 190, 180, 190, 10}) {
    const std::vector<NodeConditions> conditions = mixed_zone(k0, first, m, random);
    const Eigen::VectorXd w = bulk.displacement();
    const StepSolution s = bulk.solve(conditions, Eigen::VectorXd::Zero(m));
    ASSERT_TRUE(bulk.move(1.0));
    EXPECT_LT(step_residual(fr.problem, conditions, w, bulk.displacement(), s.normal_force,
                            s.tangential_force),
              1e-12)
        << "zone from node " << first;
  }
  EXPECT_EQ(bulk.reorders(), 0) << "each zone is a whole tail";
}

} // namespace
} // namespace sig
