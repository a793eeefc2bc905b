// The single-dof oscillator m u'' + kappa u = 0 against its exact solution u0 cos(w t) +
// (v0 / w) sin(w t), w = sqrt(kappa / m). The midpoint rule is the Cayley transform of the
// rotation generator: in (u, v / w) each step is an exact rotation by theta = 2 atan(w k / 2),
// so the amplitude is kept and the discrete period 2 pi k / theta is too long by
// (w k)^2 / 12 + O(k^4): second order.
#include "integrator/elastodynamic_march.hpp"
#include "integrator/time_scheme.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sig {
namespace {

constexpr double mass = 2.0, stiffness = 8.0, u0 = 0.3, v0 = -1.1;
const double omega = std::sqrt(stiffness / mass);
const double period = 2 * M_PI / omega;

Eigen::SparseMatrix<double> scalar(double a) {
  Eigen::SparseMatrix<double> A(1, 1);
  A.insert(0, 0) = a;
  A.makeCompressed();
  return A;
}

std::vector<double> trajectory(const std::string& scheme_name, double k, int steps) {
  Elastodynamics problem;
  problem.K = scalar(stiffness);
  problem.M = scalar(mass);
  const auto scheme = make_time_scheme(scheme_name, problem, k);
  std::vector<double> u;
  DynamicState s{0.0, Eigen::VectorXd::Constant(1, u0), Eigen::VectorXd::Constant(1, v0)};
  u.push_back(s.u(0));
  for (int n = 0; n < steps; ++n) {
    s = scheme->advance(s);
    u.push_back(s.u(0));
  }
  return u;
}

// The discrete phase per step from the trajectory: a sampled sinusoid satisfies u_{n+1} +
// u_{n-1} = 2 cos(theta) u_n, fitted by least squares.
double measured_phase(const std::vector<double>& u) {
  double num = 0, den = 0;
  for (std::size_t n = 1; n + 1 < u.size(); ++n) {
    num += (u[n + 1] + u[n - 1]) * u[n];
    den += 2 * u[n] * u[n];
  }
  return std::acos(num / den);
}

class Oscillator : public ::testing::TestWithParam<const char*> {};

TEST_P(Oscillator, IsTheExactRotationByTwiceArctanHalfWk) {
  const double k = period / 37;
  const std::vector<double> u = trajectory(GetParam(), k, 500);
  const double theta = 2 * std::atan(omega * k / 2);
  for (std::size_t n = 0; n < u.size(); ++n)
    EXPECT_NEAR(u[n], u0 * std::cos(n * theta) + v0 / omega * std::sin(n * theta), 1e-12);
}

TEST_P(Oscillator, PeriodErrorIsSecondOrder) {
  std::vector<double> period_error, end_error;
  for (int per_period : {16, 32, 64, 128}) {
    const double k = period / per_period;
    const std::vector<double> u = trajectory(GetParam(), k, 4 * per_period);
    const double discrete_period = 2 * M_PI * k / measured_phase(u);
    period_error.push_back(discrete_period / period - 1);
    // After one exact period the exact solution is back at u0.
    end_error.push_back(std::abs(u[per_period] - u0));
    // Leading term (w k)^2 / 12 of the period error, within its O(k^4) remainder.
    EXPECT_NEAR(period_error.back(), std::pow(omega * k, 2) / 12, std::pow(omega * k, 4) / 40);
  }
  for (std::size_t i = 1; i < period_error.size(); ++i) {
    EXPECT_GT(period_error[i], 0.0); // the discrete period is too long
    EXPECT_NEAR(std::log2(period_error[i - 1] / period_error[i]), 2.0, 0.05);
    EXPECT_NEAR(std::log2(end_error[i - 1] / end_error[i]), 2.0, 0.1);
  }
}

TEST_P(Oscillator, KeepsTheAmplitudeAtLargeSteps) {
  // k = 3 periods: an explicit scheme would blow up, an A-stable damped one would decay.
  Elastodynamics problem;
  problem.K = scalar(stiffness);
  problem.M = scalar(mass);
  const auto scheme = make_time_scheme(GetParam(), problem, 3 * period);
  const MarchHistory h = march(
      *scheme, {0.0, Eigen::VectorXd::Constant(1, u0), Eigen::VectorXd::Constant(1, v0)}, 200);
  const double E0 = 0.5 * mass * v0 * v0 + 0.5 * stiffness * u0 * u0;
  EXPECT_NEAR(h.steps.front().energy.total, E0, 1e-15 * E0);
  for (const StepRecord& r : h.steps)
    EXPECT_NEAR(r.energy.total, E0, 1e-12 * E0);
}

INSTANTIATE_TEST_SUITE_P(Schemes, Oscillator, ::testing::Values("midpoint", "newmark"));

} // namespace
} // namespace sig
