// The Kelvin-Voigt law with memory (material/kelvin_voigt.hpp): its cards and its MILI round
// trip (its memory in time: tests/integrator/test_memory.cpp).
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "scratch_folder.hpp"
#include "two_triangles.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>

namespace sig {
namespace {

MaterialTable table_of(const std::string& deck) {
  return material_table_from_cards(Datafile::parse(deck, "kv.dat"),
                                   test::two_triangle_square(1, 3));
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

TEST(KelvinVoigt, ViscosityIn3dIsTheThesisOperatorAndRestrictsToThe2dOne) {
  // The same operator on a 3D strain rate (e11, e22, e33, 2 e23, 2 e13, 2 e12); at e33 = e23 =
  // e13 = 0 (plane strain) its in-plane rows are the 2D D.
  const Viscosity a{0.25, 0.5};
  Eigen::Matrix<double, 6, 1> eps;
  eps << 0.3, -0.2, 0.7, 0.1, -0.6, 0.4;
  const Eigen::Matrix<double, 6, 1> sigma = a.D3() * eps;
  const double trace = eps(0) + eps(1) + eps(2);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(sigma(k), 0.25 * trace + 0.5 * eps(k)) << k;
    EXPECT_DOUBLE_EQ(sigma(3 + k), 0.5 * eps(3 + k) / 2) << 3 + k;
  }
  const int in_plane[3] = {0, 1, 5};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(a.D3()(in_plane[i], in_plane[j]), a.D()(i, j)) << i << ", " << j;
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

} // namespace
} // namespace sig
