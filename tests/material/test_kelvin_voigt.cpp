// The Kelvin-Voigt law with memory (material/kelvin_voigt.hpp, material/memory.hpp): its cards,
// its MILI round trip, and the trapezoidal memory (5.60)-(5.61), whose O(1) recursion must equal
// the direct sum and whose error in time is O(k^2).
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/memory.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "scratch_folder.hpp"
#include "two_subdomains.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

namespace sig {
namespace {

MaterialTable table_of(const std::string& deck) {
  return material_table_from_cards(Datafile::parse(deck, "kv.dat"), test::two_subdomains());
}

// The deck must fail on `line` and `field` (lower case) with `detail` in the message.
void expect_error(const std::string& deck, int line, const std::string& field,
                  const std::string& detail) {
  try {
    table_of(deck);
    ADD_FAILURE() << "no error for: " << deck;
  } catch (const InputError& e) {
    std::string f = e.field();
    for (char& c : f)
      c = static_cast<char>(std::tolower(c));
    EXPECT_EQ(e.file(), "kv.dat");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(f, field) << e.what();
    EXPECT_NE(std::string(e.what()).find(detail), std::string::npos) << e.what();
  }
}

TEST(KelvinVoigt, ViscosityIsTheThesisOperator) {
  // (A tau) = eta1 tr(tau) I + eta2 tau, Voigt vectors with the engineering shear.
  const Viscosity a{0.25, 0.5};
  const Eigen::Vector3d eps(0.3, -0.2, 0.4); // e11, e22, 2 e12
  const Eigen::Vector3d sigma = a.D() * eps;
  const double trace = eps(0) + eps(1);
  EXPECT_DOUBLE_EQ(sigma(0), 0.25 * trace + 0.5 * 0.3);
  EXPECT_DOUBLE_EQ(sigma(1), 0.25 * trace + 0.5 * -0.2);
  EXPECT_DOUBLE_EQ(sigma(2), 0.5 * 0.2);
  EXPECT_TRUE(a.D().isApprox(a.D().transpose()));
}

TEST(KelvinVoigt, CardsBuildTheLawAndItsMemory) {
  const MaterialTable table =
      table_of("MATERIAL region=1 law=kelvin-voigt E=100 nu=0.3 eta1=0.25 eta2=0.5\n"
               "MATERIAL region=3 law=kelvin-voigt E=50 nu=0.2 plane=stress\n"
               "MEMORY E=20 nu=0.3 beta=10\n"
               "MEMORY region=3 E=5 nu=0.1 beta=2\n");
  ASSERT_TRUE(table.of(1).kelvin_voigt && table.of(3).kelvin_voigt);
  const KelvinVoigt& one = *table.of(1).kelvin_voigt;
  EXPECT_EQ(one.viscosity.eta1, 0.25);
  EXPECT_EQ(one.viscosity.eta2, 0.5);
  EXPECT_EQ(table.of(1).hooke.E, 100);
  ASSERT_EQ(one.memory.size(), 1u);
  EXPECT_EQ(one.memory[0].beta, 10);
  EXPECT_EQ(one.memory[0].modulus.E, 20);
  const KelvinVoigt& three = *table.of(3).kelvin_voigt;
  EXPECT_EQ(three.viscosity.eta1, 0); // eta defaults to 0
  ASSERT_EQ(three.memory.size(), 2u);
  EXPECT_EQ(three.memory[1].beta, 2);
  EXPECT_EQ(three.memory[0].modulus.plane, PlaneMode::stress); // the plane of its sub-domain
  EXPECT_TRUE(table.has_viscosity());
  EXPECT_EQ(table.memory_terms().size(), 3u);
  EXPECT_FALSE(table_of("MATERIAL E=1 nu=0.3\n").has_viscosity());
}

TEST(KelvinVoigt, BadCardsNameLineAndField) {
  expect_error("MATERIAL law=kelvin-voigt E=100 nu=0.3 eta1=-0.25 eta2=0.5\n", 1, "eta1", ">= 0");
  expect_error("MATERIAL law=kelvin-voigt E=100 nu=0.3 eta2=-1\n", 1, "eta2", ">= 0");
  expect_error("MATERIAL law=hooke E=100 nu=0.3 eta1=1\n", 1, "eta1", "takes no field");
  const std::string law = "MATERIAL law=kelvin-voigt E=100 nu=0.3 eta1=0.25 eta2=0.5\n";
  expect_error(law + "MEMORY E=20 nu=0.3 beta=0\n", 2, "beta", "> 0");
  expect_error(law + "MEMORY E=20 nu=0.3 beta=-3\n", 2, "beta", "> 0");
  expect_error(law + "MEMORY E=20 nu=0.3\n", 2, "beta", "missing");
  expect_error(law + "MEMORY E=0 nu=0.3 beta=1\n", 2, "e", "> 0");
  expect_error(law + "MEMORY E=1 nu=0.5 beta=1\n", 2, "nu", "0.5");
  expect_error(law + "MEMORY region=2 E=1 nu=0.3 beta=1\n", 2, "region", "sub-domain 2");
  expect_error("MATERIAL region=1 E=1 nu=0.3\nMATERIAL region=3 law=kelvin-voigt E=1 nu=0.3\n"
               "MEMORY E=1 nu=0.3 beta=1\n",
               3, "region", "not law=kelvin-voigt");
}

TEST(KelvinVoigt, MiliRoundTrip) {
  const MaterialTable table =
      table_of("MATERIAL region=1 law=kelvin-voigt E=100 nu=0.3 eta1=0.25 eta2=0.5\n"
               "MATERIAL region=3 E=7 nu=0.1\n"
               "MEMORY region=1 E=20 nu=0.3 beta=10\nMEMORY region=1 E=3 nu=0.2 beta=0.5\n");
  const testing::ScratchFolder dir;
  const auto path = dir / "case.mili";
  write_mili(path, table, "kelvin-voigt");
  const MaterialTable back = read_mili(path);
  ASSERT_TRUE(back.of(1).kelvin_voigt);
  EXPECT_FALSE(back.of(3).kelvin_voigt);
  EXPECT_EQ(back.of(1).kelvin_voigt->viscosity.eta2, 0.5);
  ASSERT_EQ(back.of(1).kelvin_voigt->memory.size(), 2u);
  EXPECT_EQ(back.of(1).kelvin_voigt->memory[1].beta, 0.5);
  EXPECT_EQ(back.of(1).kelvin_voigt->memory[1].modulus.nu, 0.2);
  EXPECT_EQ(back.of(1).hooke.E, 100);
}

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
