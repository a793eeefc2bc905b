// The contact Newton driver in 3D (issue 26): friction with two tangential unknowns per node, the
// tangential force projected on the disc of radius s (the Coulomb cone's section), on the
// condensed linear bulk. Requirements:
//  - the driver's eliminated step is the Alart-Curnier generalized Newton step of the 3D kernel,
//    solved densely, at an iterate with nodes on the wall and off it, sticking and slipping (the
//    slip branch's curvature s (I - e e^T) / |z| included);
//  - a 2D problem laid in 3D (a second tangent decoupled, unloaded) gives the 2D solution;
//  - a converged 3D solve obeys the cone at every node: N >= 0 on the wall, |T| <= s, T = s e
//    along the slip where the node slips, no slip where it sticks, and the equilibrium.
#include "contact/contact_kernel.hpp"
#include "frictional_problem.hpp"
#include "solver/condensed_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <random>

namespace sig {
namespace {

using test::coulomb;
using test::Frictional;
using test::tresca;

ContactSolverParameters parameters_for(const std::string& method) {
  ContactSolverParameters parameters;
  parameters.method = method;
  const bool penalty = method == "penalty";
  // Penalty's springs at 1e4 times the bulk's stiffness: at 1e6 (the 2D tests' value) its
  // Newton stalls in 3D with the branches settled, the slip's curvature s / |q_t| of the nodes
  // that barely slip limiting every step (1e2 to 1e5 converge).
  parameters.r = penalty ? 1e4 : 10;
  parameters.gamma = parameters.c = 10;
  parameters.eps = penalty ? 1e-9 : 1e-10;
  parameters.max_iterations = 100;
  return parameters;
}

/// m contact nodes with (w_t1, w_t2, w_n) each (d unknowns), a dense SPD S coupling all of them,
/// a load pressing them onto the obstacle and pushing them along an oblique direction of the
/// tangent plane (so that some stick and some slip), gaps from 0 (touching) to out of reach.
Frictional frictional_problem_3d(const ContactLaw& law, int m = 9, double push = 0.5) {
  return test::random_frictional_problem(3, m, 11, law, [push](int c, double u) {
    return c == 0 ? push * (1 + 0.8 * u) : c == 1 ? push * (0.6 + 0.8 * u) : 1.5 + 0.5 * u;
  });
}

/// One generalized Newton step on X = (w, lambda, t) (nodal-force multipliers, t two per node)
/// of R_w = S w - f + sum_q w_q (N_q e_n + T_q . e_t), R_lambda = w C_n, R_t = w C_t, with the 3D
/// kernel's forces and derivatives, solved densely.
Eigen::VectorXd dense_step_3d(const Frictional& fr, const Eigen::VectorXd& X, double r) {
  const CondensedProblem& p = fr.problem;
  const int m = fr.setting.size(), n = static_cast<int>(p.f.size()), size = n + 3 * m;
  Eigen::VectorXd R = Eigen::VectorXd::Zero(size);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(size, size);
  R.head(n) = p.S * X.head(n) - p.f;
  J.topLeftCorner(n, n) = p.S;
  for (int q = 0; q < m; ++q) {
    const double w = fr.setting.weight[q];
    const int dn = p.normal_dof[q], dt1 = p.tangential_dof[2 * q],
              dt2 = p.tangential_dof[2 * q + 1];
    NodeVariablesIn<3> x;
    x.q_n = X[dn] - p.gap[q];
    x.q_t = Eigen::Vector2d(X[dt1], X[dt2]);
    x.lambda = X[n + q] / w;
    x.t = X.segment<2>(n + m + 2 * q) / w;
    const ContactKernelIn<3> k =
        contact_kernel(fr.setting.law[q], x, r, std::min(r, p.S(dn, dn) / w));
    const int column[6] = {dn, dt1, dt2, n + q, n + m + 2 * q, n + m + 2 * q + 1};
    const double scale[6] = {1.0, 1.0, 1.0, 1.0 / w, 1.0 / w, 1.0 / w};
    const int force_row[3] = {dn, dt1, dt2};
    const int complementarity_row[3] = {n + q, n + m + 2 * q, n + m + 2 * q + 1};
    for (int i = 0; i < 3; ++i) {
      R[force_row[i]] += w * (i == 0 ? k.normal : k.tangential[i - 1]);
      R[complementarity_row[i]] = w * k.complementarity[i];
      for (int j = 0; j < 6; ++j) {
        J(force_row[i], column[j]) += w * k.d_force(i, j) * scale[j];
        J(complementarity_row[i], column[j]) = w * k.d_complementarity(i, j) * scale[j];
      }
    }
  }
  return X - J.fullPivLu().solve(R);
}

TEST(ContactNewton3d, TheStepIsTheAlartCurnierNewtonStep) {
  for (const ContactLaw& law : {coulomb(0.3), tresca(0.4)})
    for (const char* method : {"alm", "pdas"}) {
      const Frictional fr = frictional_problem_3d(law, 9, 0.1);
      const int m = fr.setting.size(), n = static_cast<int>(fr.problem.f.size());
      // An iterate away from the solution: some nodes on the wall, some sticking, some slipping.
      std::mt19937 random(3);
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      Eigen::VectorXd X(n + 3 * m);
      for (int i = 0; i < n + 3 * m; ++i)
        X[i] = (i >= n + m ? 0.1 : 0.3) * uniform(random) + (i >= n && i < n + m ? 0.4 : 0.0);
      for (int q = 0; q < m; q += 2) // nodes that barely slipped: they stick
        for (int k = 0; k < 2; ++k) {
          X[3 * q + k] *= 0.01;
          X[n + m + 2 * q + k] *= 0.01;
        }
      const std::unique_ptr<ContactMethod> newton = make_contact_method(parameters_for(method));
      CondensedBulk bulk(fr.problem, {}, X.head(n));
      ASSERT_EQ(bulk.tangents(), 2);
      ContactIterate iterate{X.segment(n, m), X.tail(2 * m), {}};
      ContactNewtonOptions full{1e-12, 1};
      full.globalize = false; // the full step, to compare with the dense one
      const ContactNewtonResult c = solve_contact(bulk, fr.setting, *newton, full, iterate);
      ASSERT_EQ(c.iterations(), 1) << c.failure;
      ASSERT_GT(c.history[0].active, 0);
      ASSERT_LT(c.history[0].active, m);
      ASSERT_GT(c.history[0].stick, 0) << describe(law) << " " << method;
      ASSERT_GT(c.history[0].slip, 0) << describe(law) << " " << method;
      const Eigen::VectorXd expected = dense_step_3d(fr, X, newton->augmentation());
      const double tol = 1e-10 * expected.cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(bulk.displacement()[i], expected[i], tol) << method << " w " << i;
      for (int q = 0; q < m; ++q)
        EXPECT_NEAR(iterate.lambda[q], expected[n + q], tol) << method << " lambda " << q;
      for (int q = 0; q < 2 * m; ++q)
        EXPECT_NEAR(iterate.t[q], expected[n + m + q], tol) << method << " t " << q;
    }
}

/// The 2D frictional problem (w_t, w_n per node) laid in 3D: a second tangent per node with its
/// own stiffness k, coupled to nothing and unloaded.
Frictional laid_in_3d(const Frictional& plane, double k) {
  const CondensedProblem& p = plane.problem;
  const int m = plane.setting.size(), n = static_cast<int>(p.f.size());
  Frictional fr;
  CondensedProblem& q = fr.problem;
  q.S = Eigen::MatrixXd::Zero(n + m, n + m);
  q.S.topLeftCorner(n, n) = p.S;
  q.f = Eigen::VectorXd::Zero(n + m);
  q.f.head(n) = p.f;
  q.gap = p.gap;
  q.normal_dof = p.normal_dof;
  q.regularization = p.regularization;
  for (int a = 0; a < m; ++a) {
    q.S(n + a, n + a) = k;
    q.tangential_dof.push_back(p.tangential_dof[a]);
    q.tangential_dof.push_back(n + a);
  }
  fr.setting = plane.setting;
  return fr;
}

/// The 2D problem of test_contact_newton.cpp's frictional tests: a load along +t.
Frictional frictional_problem_2d(const ContactLaw& law, int m = 9) {
  Frictional fr = frictional_problem_3d(law, m);
  CondensedProblem& p = fr.problem;
  std::vector<int> keep;
  for (int q = 0; q < m; ++q) {
    keep.push_back(3 * q);
    keep.push_back(3 * q + 2);
  }
  CondensedProblem plane;
  const int n = static_cast<int>(keep.size());
  plane.S.resize(n, n);
  plane.f.resize(n);
  for (int i = 0; i < n; ++i) {
    plane.f[i] = p.f[keep[i]];
    for (int j = 0; j < n; ++j)
      plane.S(i, j) = p.S(keep[i], keep[j]);
  }
  for (int q = 0; q < m; ++q) {
    plane.tangential_dof.push_back(2 * q);
    plane.normal_dof.push_back(2 * q + 1);
  }
  plane.gap = p.gap;
  fr.problem = plane;
  return fr;
}

TEST(ContactNewton3d, ATwoDimensionalProblemLaidInThreeGivesItsSolution) {
  for (const ContactLaw& law : {coulomb(0.3), tresca(0.4)})
    for (const char* method : {"alm", "pdas", "projection", "penalty"}) {
      const Frictional plane = frictional_problem_2d(law);
      const Frictional space = laid_in_3d(plane, 3.0);
      const CondensedSolution a =
          solve_condensed_contact(plane.problem, plane.setting, parameters_for(method));
      const CondensedSolution b =
          solve_condensed_contact(space.problem, space.setting, parameters_for(method));
      ASSERT_TRUE(a.contact.converged) << method << ": " << a.contact.failure;
      ASSERT_TRUE(b.contact.converged) << method << ": " << b.contact.failure;
      const int m = plane.setting.size();
      ASSERT_EQ(b.contact.tangential_force.size(), 2 * m);
      const double scale = a.contact.normal_force.cwiseAbs().maxCoeff();
      const double tol = (std::string(method) == "penalty" ? 1e-8 : 1e-10) * scale;
      int stick = 0, slip = 0;
      for (int q = 0; q < m; ++q) {
        EXPECT_NEAR(b.contact.normal_force[q], a.contact.normal_force[q], tol) << method << q;
        EXPECT_NEAR(b.contact.tangential_force[2 * q], a.contact.tangential_force[q], tol)
            << method << " " << q;
        EXPECT_NEAR(b.contact.tangential_force[2 * q + 1], 0.0, tol) << method << " " << q;
        EXPECT_EQ(b.contact.normal_status[q], a.contact.normal_status[q]) << method << " " << q;
        const bool stuck = a.contact.friction_status[q] == FrictionStatus::stick;
        EXPECT_EQ(b.contact.friction_status[q] == FrictionStatus::stick, stuck)
            << method << " " << q;
        stick += stuck;
        slip += !stuck && a.contact.friction_status[q] != FrictionStatus::none;
      }
      EXPECT_GT(stick, 0) << describe(law) << " " << method << ": the test needs sticking nodes";
      EXPECT_GT(slip, 0) << describe(law) << " " << method << ": and slipping ones";
      for (Eigen::Index i = 0; i < plane.problem.f.size(); ++i)
        EXPECT_NEAR(b.w[i], a.w[i], 1e-9 * a.w.cwiseAbs().maxCoeff()) << method << " w " << i;
    }
}

class ConeMethods : public ::testing::TestWithParam<const char*> {};

TEST_P(ConeMethods, TheSolutionObeysTheCone) {
  for (const ContactLaw& law : {coulomb(0.3), tresca(0.4)}) {
    const Frictional fr = frictional_problem_3d(law, 9, 0.1);
    const CondensedProblem& p = fr.problem;
    const CondensedSolution s = solve_condensed_contact(p, fr.setting, parameters_for(GetParam()));
    ASSERT_TRUE(s.contact.converged)
        << GetParam() << " " << describe(law) << ": " << s.contact.failure;
    const bool penalty = std::string(GetParam()) == "penalty";
    const double scale = s.contact.normal_force.cwiseAbs().maxCoeff();
    const double tol = (penalty ? 1e-5 : 1e-9) * scale;
    Eigen::VectorXd r = p.S * s.w - p.f;
    int stick = 0, slip = 0;
    for (int q = 0; q < fr.setting.size(); ++q) {
      const double N = s.contact.normal_force[q];
      const Eigen::Vector2d T = s.contact.tangential_force.segment<2>(2 * q);
      const Eigen::Vector2d q_t(s.w[p.tangential_dof[2 * q]], s.w[p.tangential_dof[2 * q + 1]]);
      r[p.normal_dof[q]] += N;
      r[p.tangential_dof[2 * q]] += T[0];
      r[p.tangential_dof[2 * q + 1]] += T[1];
      const double bound =
          law.friction == FrictionLaw::coulomb ? law.mu * N : law.threshold * fr.setting.weight[q];
      EXPECT_GE(N, -tol) << q;
      EXPECT_LE(T.norm(), bound + tol) << GetParam() << " " << describe(law) << " " << q;
      const FrictionStatus status = s.contact.friction_status[q];
      if (status == FrictionStatus::stick && !penalty) {
        ++stick;
        EXPECT_LT(q_t.norm(), 1e-9) << GetParam() << " " << q;
      } else if (status == FrictionStatus::slip_forward) {
        ++slip;
        // T = s e, e = z / |z| with z = t + r q_t: at the solution along the slip itself.
        EXPECT_NEAR(T.norm(), bound, tol) << GetParam() << " " << describe(law) << " " << q;
        EXPECT_NEAR(T.dot(q_t), T.norm() * q_t.norm(), 1e-7 * T.norm() * q_t.norm())
            << GetParam() << " " << describe(law) << " " << q;
      } else if (status == FrictionStatus::stick) {
        ++stick;
      }
    }
    EXPECT_LT(r.norm(), 1e-8 * p.f.norm()) << GetParam();
    EXPECT_GT(stick, 0) << GetParam() << " " << describe(law) << ": the test needs sticking nodes";
    EXPECT_GT(slip, 0) << GetParam() << " " << describe(law) << ": and slipping ones";
  }
}

INSTANTIATE_TEST_SUITE_P(ContactMethods, ConeMethods,
                         ::testing::Values("alm", "penalty", "pdas", "projection"));

} // namespace
} // namespace sig
