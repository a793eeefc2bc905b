// MATERIAL cards -> material table -> MILI file and back.
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "input_error.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "scratch_folder.hpp"
#include "two_triangles.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

namespace sig {
namespace {

const Card& first_card(const Datafile& d) {
  return d.cards().front();
}

using testing::input_error;

TEST(MaterialCard, ReadsLawThicknessAndDensity) {
  const Datafile d = Datafile::parse(
      "MATERIAL law=hooke E=200 nu=0.3 plane=stress thickness=0.1 rho=7800\n", "m.dat");
  const SubdomainMaterial m = material_from_card(first_card(d));
  EXPECT_DOUBLE_EQ(m.hooke.E, 200);
  EXPECT_DOUBLE_EQ(m.hooke.nu, 0.3);
  EXPECT_EQ(m.hooke.plane, PlaneMode::stress);
  EXPECT_DOUBLE_EQ(m.thickness, 0.1);
  EXPECT_DOUBLE_EQ(m.density, 7800);
  const Datafile defaults = Datafile::parse("MATERIAL E=1 nu=0\n", "m.dat");
  const SubdomainMaterial n = material_from_card(first_card(defaults));
  EXPECT_EQ(n.hooke.plane, PlaneMode::strain);
  EXPECT_DOUBLE_EQ(n.thickness, 1.0);
  EXPECT_DOUBLE_EQ(n.density, 0.0);
}

TEST(MaterialCard, IncompressibleLimitIsRejectedOnFieldNu) {
  const Datafile d = Datafile::parse("# units: GPa\nMATERIAL law=hooke E=1 nu=0.5\n", "m.dat");
  const InputError e = input_error([&] { material_from_card(first_card(d)); });
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.field(), "nu");
  EXPECT_NE(std::string(e.what()).find("nu"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("incompressible"), std::string::npos) << e.what();
}

TEST(MaterialCard, RejectsOutOfRangeParameters) {
  struct Case {
    const char* text;
    const char* field;
  };
  for (const Case c :
       {Case{"MATERIAL E=0 nu=0.3", "e"}, Case{"MATERIAL E=-2 nu=0.3", "e"},
        Case{"MATERIAL E=1 nu=-1", "nu"}, Case{"MATERIAL E=1 nu=0.7", "nu"},
        Case{"MATERIAL E=1 nu=0.3 thickness=0", "thickness"},
        Case{"MATERIAL E=1 nu=0.3 rho=-1", "rho"}, Case{"MATERIAL law=ogden E=1 nu=0.3", "law"}}) {
    const Datafile d = Datafile::parse(std::string(c.text) + "\n", "m.dat");
    const InputError e = input_error([&] { material_from_card(first_card(d)); });
    std::string field = e.field();
    for (char& ch : field)
      ch = static_cast<char>(std::tolower(ch));
    EXPECT_EQ(field, c.field) << c.text << ": " << e.what();
    EXPECT_EQ(e.line(), 1);
  }
}

TEST(MaterialTable, OneLawPerSubdomain) {
  const Mesh mesh = test::two_triangle_square(1, 3);
  const Datafile d = Datafile::parse("MATERIAL region=3 E=2 nu=0.1\n"
                                     "MATERIAL region=1 E=1 nu=0.2 rho=5\n",
                                     "m.dat");
  const MaterialTable table = material_table_from_cards(d, mesh);
  ASSERT_EQ(table.entries.size(), 2u);
  EXPECT_EQ(table.entries[0].subdomain, 1);
  EXPECT_EQ(table.of(1).hooke.E, 1.0);
  EXPECT_EQ(table.of(3).hooke.E, 2.0);
  EXPECT_TRUE(table.has_mass());
  EXPECT_THROW(table.of(2), Error);
}

TEST(MaterialTable, CardWithoutRegionCoversEverySubdomain) {
  const Datafile d = Datafile::parse("MATERIAL E=4 nu=0.25\n", "m.dat");
  const MaterialTable table = material_table_from_cards(d, test::two_triangle_square(1, 3));
  ASSERT_EQ(table.entries.size(), 2u);
  EXPECT_EQ(table.of(1).hooke.E, 4.0);
  EXPECT_EQ(table.of(3).hooke.E, 4.0);
  EXPECT_FALSE(table.has_mass());
}

TEST(MaterialTable, MissingDuplicateOrUnknownSubdomainIsAnInputError) {
  const Mesh mesh = test::two_triangle_square(1, 3);
  const Datafile missing = Datafile::parse("MATERIAL region=1 E=1 nu=0.2\n", "m.dat");
  const InputError e1 = input_error([&] { material_table_from_cards(missing, mesh); });
  EXPECT_EQ(e1.line(), 1);
  EXPECT_NE(std::string(e1.what()).find("sub-domain 3"), std::string::npos) << e1.what();

  const Datafile twice =
      Datafile::parse("MATERIAL E=1 nu=0.2\n\nMATERIAL region=3 E=1 nu=0.2\n", "m.dat");
  const InputError e2 = input_error([&] { material_table_from_cards(twice, mesh); });
  EXPECT_EQ(e2.line(), 3);
  EXPECT_EQ(e2.field(), "region");

  const Datafile unknown = Datafile::parse("MATERIAL region=1,2 E=1 nu=0.2\n", "m.dat");
  const InputError e3 = input_error([&] { material_table_from_cards(unknown, mesh); });
  EXPECT_EQ(e3.field(), "region");
  EXPECT_NE(std::string(e3.what()).find("sub-domain 2"), std::string::npos) << e3.what();

  const Datafile none = Datafile::parse("TITLE no law\n", "m.dat");
  EXPECT_THROW(material_table_from_cards(none, mesh), InputError);
}

TEST(Mili, RoundTrip) {
  MaterialTable table;
  SubdomainMaterial a;
  a.subdomain = 1;
  a.hooke = {200.0, 0.3, PlaneMode::strain};
  a.thickness = 1.0;
  a.density = 0.0;
  SubdomainMaterial b;
  b.subdomain = 4;
  b.hooke = {0.07, -0.25, PlaneMode::stress};
  b.thickness = 0.125;
  b.density = 1000.0;
  table.entries = {a, b};
  const testing::ScratchFolder dir;
  const auto path = dir / "case.mili";
  write_mili(path, table, "round trip");
  const MaterialTable back = read_mili(path);
  ASSERT_EQ(back.entries.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const SubdomainMaterial& x = table.entries[i];
    const SubdomainMaterial& y = back.entries[i];
    EXPECT_EQ(x.subdomain, y.subdomain);
    EXPECT_EQ(x.hooke.E, y.hooke.E);
    EXPECT_EQ(x.hooke.nu, y.hooke.nu);
    EXPECT_EQ(x.hooke.plane, y.hooke.plane);
    EXPECT_EQ(x.thickness, y.thickness);
    EXPECT_EQ(x.density, y.density);
  }
}

TEST(Mili, WrongKindIsRejected) {
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_ds(path, Ds("TAE", "not a mili", "test"));
  EXPECT_THROW(read_mili(path), Error);
}

// sig-assemble took a case.mili with nu = NaN, 0.5, E < 0 or thickness 0 and wrote a NaN
// stiffness: the MATERIAL card's ranges hold for the file (core/ranges.hpp), each refusal naming
// the file, the array and the row.
TEST(Mili, ValuesOutOfTheCardsRangesAreRefused) {
  const testing::ScratchFolder dir;
  const auto path = dir / "case.mili";
  MaterialTable table;
  SubdomainMaterial a;
  a.hooke = {200.0, 0.3, PlaneMode::strain};
  table.entries = {a};
  write_mili(path, table, "ranges");
  const Ds good = read_ds(path, "MILI");
  struct Damage {
    const char* array;
    double value;
    const char* expected;
  };
  for (const Damage& d : {Damage{"poisson", 0.5, "array 'poisson', row 1: 0.5 is not in (-1, 0.5)"},
                          Damage{"poisson", NAN, "array 'poisson': value 1 of 1 is NaN"},
                          Damage{"young", -3, "array 'young', row 1: -3 is not > 0"},
                          Damage{"thickness", 0, "array 'thickness', row 1: 0 is not > 0"},
                          Damage{"density", -1, "array 'density', row 1: -1 is not >= 0"}}) {
    Ds bad = good;
    bad.put(d.array, std::vector<double>{d.value}, {}, Finite::not_required);
    write_ds(path, bad);
    try {
      read_mili(path);
      ADD_FAILURE() << d.array << " = " << d.value << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + ": " + d.expected), std::string::npos)
          << e.what();
    }
  }
}

} // namespace
} // namespace sig
