// The trapezoidal memory (5.60)-(5.61) of the Kelvin-Voigt law (integrator/memory.hpp): its O(1)
// recursion must equal the direct sum and its error in time is O(k^2).
#include "core/error.hpp"
#include "integrator/memory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace sig {
namespace {

// The O(1) recursion equals the direct sum (5.61) to round-off, at every step, for several
// decay rates and a nonzero w_0.
TEST(TrapezoidalMemory, RecursionEqualsTheDirectSum) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> value(-1, 1);
  const auto vector = [&] {
    Eigen::VectorXd v(7);
    for (double& x : v)
      x = value(random);
    return v;
  };
  for (double beta : {0.1, 10.0, 300.0})
    for (double k : {1.0 / 64, 0.3}) {
      std::vector<Eigen::VectorXd> w{vector()};
      ExponentialMemory memory(beta, k, w[0]);
      const auto kernel = [beta](double t) { return std::exp(-beta * t); };
      for (int n = 1; n <= 200; ++n) {
        w.push_back(vector());
        // C_n = k (P_n + w_n / 2) for K = exp(-beta t) times the identity.
        const Eigen::VectorXd recursive = k * (memory.history() + 0.5 * w.back());
        const Eigen::VectorXd direct = trapezoidal_memory(kernel, k, w);
        ASSERT_LE((recursive - direct).norm(), 1e-14 * (1 + direct.norm()))
            << "beta " << beta << " k " << k << " n " << n;
        memory.advance(w.back());
      }
    }
}

// The trapezoidal rule's error on a smooth history is O(k^2): for w(s) = cos(s),
// int_0^t exp(-beta (t - s)) cos(s) ds = (beta cos t + sin t - beta exp(-beta t)) / (1 + beta^2).
TEST(TrapezoidalMemory, SecondOrderInTime) {
  const double beta = 3.0, T = 1.0;
  const double exact =
      (beta * std::cos(T) + std::sin(T) - beta * std::exp(-beta * T)) / (1 + beta * beta);
  double previous = 0;
  for (int N : {16, 32, 64, 128}) {
    const double k = T / N;
    ExponentialMemory memory(beta, k, Eigen::VectorXd::Constant(1, 1.0)); // w_0 = cos 0
    for (int n = 1; n < N; ++n)
      memory.advance(Eigen::VectorXd::Constant(1, std::cos(n * k)));
    const double error = std::abs(k * (memory.history()[0] + 0.5 * std::cos(T)) - exact);
    if (previous > 0) {
      EXPECT_NEAR(previous / error, 4.0, 0.05) << "N " << N;
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

TEST(TrapezoidalMemory, RefusesBadParameters) {
  EXPECT_THROW(ExponentialMemory(0.0, 0.1, Eigen::VectorXd::Zero(2)), Error);
  EXPECT_THROW(ExponentialMemory(1.0, -0.1, Eigen::VectorXd::Zero(2)), Error);
  ExponentialMemory memory(1.0, 0.1, Eigen::VectorXd::Zero(2));
  EXPECT_THROW(memory.advance(Eigen::VectorXd::Zero(3)), Error);
  EXPECT_EQ(trapezoidal_memory([](double) { return 1.0; }, 0.1, {Eigen::VectorXd::Ones(2)}).norm(),
            0.0);
}

} // namespace
} // namespace sig
