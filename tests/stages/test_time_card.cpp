// The TIME and INITIAL cards of sig-march: a good card gives the step count T / k, every bad
// field is refused with the file, the line and the field named, and the INITIAL cards place
// their uniform fields on the nodes of their sub-domains only.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "mesh/gmsh.hpp"
#include "stages/time_card.hpp"
#include "test_bodies.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sig {
namespace {

Datafile deck(const std::string& time_card) {
  return Datafile::parse("TITLE dynamics\n" + time_card + "\n", "deck.dat");
}

// The InputError of `time_card` (line 2 of the deck), or a test failure if it is accepted.
InputError refusal(const std::string& time_card, bool has_contact = false) {
  const Datafile d = deck(time_card);
  try {
    time_parameters(d.require("TIME"), has_contact);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << time_card;
  return InputError("", 0, "", "");
}

TEST(TimeCard, GoodCardGivesTheStepCount) {
  const Datafile d = deck("TIME scheme=newmark T=2 k=1e-3 output_every=50 mass=lumped");
  const TimeParameters p = time_parameters(d.require("TIME"), false);
  EXPECT_EQ(p.scheme, "newmark");
  EXPECT_EQ(p.steps, 2000); // 2 / 1e-3 is 1999.9999999999998 in floating point
  EXPECT_DOUBLE_EQ(p.k, 1e-3);
  EXPECT_EQ(p.output_every, 50);
  EXPECT_EQ(p.mass, MassChoice::lumped);
  const TimeParameters q =
      time_parameters(deck("TIME scheme=midpoint T=1 k=0.1").require("TIME"), false);
  EXPECT_EQ(q.steps, 10);
  EXPECT_EQ(q.output_every, 1);
  EXPECT_EQ(q.mass, MassChoice::consistent);
}

TEST(TimeCard, BadFieldsAreRefusedWithFileLineAndField) {
  const struct {
    const char* card;
    const char* field;
  } cases[] = {
      {"TIME scheme=midpoint T=1 k=-1", "k"},
      {"TIME scheme=midpoint T=1 k=0", "k"},
      {"TIME scheme=midpoint T=0 k=0.1", "T"},
      {"TIME scheme=midpoint T=1 k=0.3", "k"}, // 3.33 steps
      {"TIME scheme=midpoint T=1 k=0.1 output_every=0", "output_every"},
      {"TIME scheme=euler T=1 k=0.1", "scheme"},
      {"TIME scheme=midpoint T=1 k=0.1 mass=emm", "mass"},
  };
  for (const auto& c : cases) {
    const InputError e = refusal(c.card);
    EXPECT_EQ(e.file(), "deck.dat") << c.card;
    EXPECT_EQ(e.line(), 2) << c.card;
    EXPECT_EQ(e.field(), c.field) << c.card;
  }
  EXPECT_NE(std::string(refusal("TIME scheme=midpoint T=1 k=0.1 mass=emm").what()).find("CONTACT"),
            std::string::npos);
}

TEST(TimeCard, EmmIsAcceptedWithContact) {
  const Datafile d = deck("TIME scheme=midpoint T=1 k=0.1 mass=emm");
  EXPECT_EQ(time_parameters(d.require("TIME"), true).mass, MassChoice::emm);
}

TEST(InitialCards, UniformFieldsOnTheirSubDomains) {
  Mesh mesh = test::perturbed_rectangle(2.0, 1.0, 4, 2);
  // Sub-domain 2: the triangles right of x = 1.
  for (int t = 0; t < mesh.num_cells(); ++t) {
    double cx = 0;
    for (int node : mesh.cells[t])
      cx += mesh.nodes[node].x() / 3;
    mesh.subdomain[t] = cx > 1.0 ? 2 : 1;
  }
  const Datafile d = Datafile::parse("INITIAL u=0.5,0 v=1,-2\nINITIAL v=3,4 region=2\n", "i.dat");
  const InitialFields f = initial_fields(d, mesh);
  ASSERT_EQ(f.u.size(), 2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    bool in_region_2 = false;
    for (int t = 0; t < mesh.num_cells(); ++t)
      for (int node : mesh.cells[t])
        in_region_2 |= node == i && mesh.subdomain[t] == 2;
    EXPECT_EQ(f.u.segment<2>(2 * i), Eigen::Vector2d(0.5, 0.0));
    const Eigen::Vector2d v = in_region_2 ? Eigen::Vector2d(3, 4) : Eigen::Vector2d(1, -2);
    EXPECT_EQ(f.v.segment<2>(2 * i), v) << "node " << i;
  }
  EXPECT_THROW(initial_fields(Datafile::parse("INITIAL v=1,2,3\n", "i.dat"), mesh), InputError);
  EXPECT_THROW(initial_fields(Datafile::parse("INITIAL v=1,2 region=5\n", "i.dat"), mesh),
               InputError);
  EXPECT_EQ(initial_fields(Datafile::parse("TITLE none\n", "i.dat"), mesh).v.norm(), 0.0);
}

// On a 3D mesh (issue 28) every vector has three components, and the spin is the vector omega:
// v + omega x (X - centre) at every node; two components are refused on the card's line.
TEST(InitialCards, ThreeDimensionalTranslationAndSpin) {
  const Mesh mesh = read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" /
                              "gmsh" / "box_v41_ascii.msh");
  ASSERT_EQ(mesh.dim, 3);
  const Datafile d =
      Datafile::parse("INITIAL u=0.5,0,-1 v=1,-2,3 omega=0.1,0.2,-0.3 centre=0.5,0.5,0\n", "i.dat");
  const InitialFields f = initial_fields(d, mesh);
  ASSERT_EQ(f.v.size(), 3 * mesh.num_nodes());
  const Eigen::Vector3d omega(0.1, 0.2, -0.3), centre(0.5, 0.5, 0.0);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d x = mesh.nodes[static_cast<std::size_t>(i)];
    EXPECT_EQ(f.u.segment<3>(3 * i), Eigen::Vector3d(0.5, 0.0, -1.0));
    EXPECT_LT((f.v.segment<3>(3 * i) - Eigen::Vector3d(1, -2, 3) - omega.cross(x - centre)).norm(),
              1e-15)
        << "node " << i;
  }
  try {
    initial_fields(Datafile::parse("TITLE t\nINITIAL v=1,2\n", "i.dat"), mesh);
    ADD_FAILURE() << "a 2D velocity on a 3D mesh accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("i.dat:2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("three components"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace sig
