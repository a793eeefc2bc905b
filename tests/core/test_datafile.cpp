// The datafile reader: a good deck in all its spellings, and for each kind of mistake an
// InputError that points at the file, the line and the field.
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/ranges.hpp"
#include "scratch_folder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <set>

namespace sig {
namespace {

using sig::testing::ScratchFolder;

const char* good_deck = "# Hertz contact, GPa-m units\n"
                        "title Hertz: half disc # on a rigid plane\n"
                        "\n"
                        "Mesh  Generator=Half-Disc R=1 n = 8 center=0,1   # comment\n"
                        "MATERIAL region=1 law=hooke E=210 NU=0.3 plane=STRAIN\r\n"
                        "material region=2 law=Hooke E=7e1 nu=.25 plane=stress thickness=+2\n"
                        "  TRACTION ref=3 f=0, -2.5e-3\n"
                        "CONTACT ref=2 obstacle=plane point=0,0 normal=0,-1 gap=0\n"
                        "OUTPUT name=\"Hertz # N=8\" vtk=yes\n"
                        "MESH_COMMENT_FREE_LINE_FOLLOWS\n";

TEST(Datafile, GoodDeckParses) {
  // The last line of good_deck is an unknown card: cut it for this test.
  std::string text = good_deck;
  text = text.substr(0, text.find("MESH_COMMENT"));
  const Datafile deck = Datafile::parse(text, "decks/hertz.dat");
  EXPECT_EQ(deck.path, "decks/hertz.dat");
  ASSERT_EQ(deck.cards().size(), 7u);
  EXPECT_EQ(deck.title(), "Hertz: half disc");
  EXPECT_EQ(deck.stem(), "hertz");

  const Card& mesh = deck.require("mesh");
  EXPECT_EQ(mesh.keyword, "MESH");
  EXPECT_EQ(mesh.line, 4);
  EXPECT_EQ(mesh.file, "decks/hertz.dat");
  EXPECT_EQ(mesh.text("generator"), "Half-Disc"); // values keep their case
  EXPECT_EQ(mesh.choice("generator", {"half-disc", "disc"}), "half-disc");
  EXPECT_EQ(mesh.real("R"), 1.0);
  EXPECT_EQ(mesh.real("r"), 1.0); // field names are case-insensitive
  EXPECT_EQ(mesh.integer("N"), 8);
  EXPECT_EQ(mesh.reals("center"), (std::vector<double>{0, 1}));
  EXPECT_EQ(mesh.fields.front().first, "generator"); // stored lower case, in order
  EXPECT_EQ(mesh.fields[1].first, "r");
  EXPECT_FALSE(mesh.has("file"));
  EXPECT_EQ(mesh.real("grading", 1.5), 1.5);
  EXPECT_EQ(mesh.integer("layers", 4), 4);
  EXPECT_EQ(mesh.text("file", "none"), "none");

  const auto materials = deck.all("Material");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0]->line, 5);
  EXPECT_EQ(materials[0]->real("e"), 210.0);
  EXPECT_EQ(materials[0]->real("nu"), 0.3);
  EXPECT_EQ(materials[0]->choice("plane", {"strain", "stress"}), "strain");
  EXPECT_EQ(materials[0]->text("plane"), "STRAIN"); // the CR of a CRLF line is not kept
  EXPECT_EQ(materials[1]->real("E"), 70.0);
  EXPECT_EQ(materials[1]->real("nu"), 0.25);
  EXPECT_EQ(materials[1]->real("thickness"), 2.0);
  EXPECT_EQ(materials[1]->integers("region"), (std::vector<long>{2}));
  EXPECT_EQ(materials[1]->choice("law", {"hooke"}), "hooke");
  EXPECT_EQ(materials[1]->real("rho", 0.0), 0.0);

  EXPECT_EQ(deck.require("TRACTION").reals("f"), (std::vector<double>{0, -2.5e-3}));
  const Card& contact = deck.require("contact");
  EXPECT_EQ(contact.reals("normal"), (std::vector<double>{0, -1}));
  EXPECT_EQ(contact.integer("ref"), 2);
  const Card& output = deck.require("OUTPUT");
  EXPECT_EQ(output.text("name"), "Hertz # N=8"); // a '#' inside quotes is not a comment
  EXPECT_EQ(output.choice("vtk", {"yes", "no"}), "yes");
  EXPECT_EQ(deck.find("SOLVER"), nullptr);
  EXPECT_EQ(deck.all("DIRICHLET").size(), 0u);
}

TEST(Datafile, TitleDefaultsToTheFileStemAndQuotesAreOptional) {
  EXPECT_EQ(Datafile::parse("MESH generator=disc\n", "a/ring_b.dat").title(), "ring_b");
  EXPECT_EQ(Datafile::parse("TITLE \"Quoted   title\"\n", "x.dat").title(), "Quoted   title");
  EXPECT_EQ(Datafile::parse("", "empty.dat").cards().size(), 0u);
}

TEST(Datafile, ReadsFromDiskAndResolvesFilesFromItsFolder) {
  ScratchFolder dir;
  std::filesystem::create_directories(dir / "decks");
  sig::testing::spit(dir / "decks" / "ring.dat",
                     "MESH file=../meshes/Ring.msh\nOUTPUT name=/abs/out\n");
  const Datafile deck = Datafile::read(dir / "decks" / "ring.dat");
  EXPECT_EQ(deck.path, (dir / "decks" / "ring.dat").string());
  EXPECT_EQ(deck.require("MESH").path("file"), dir / "decks" / "../meshes/Ring.msh");
  EXPECT_EQ(deck.require("OUTPUT").path("name"), std::filesystem::path("/abs/out"));

  try {
    Datafile::read(dir / "absent.dat");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "absent.dat").string()), std::string::npos);
  }
}

TEST(Datafile, InputErrorMessageForm) {
  EXPECT_STREQ(InputError("d.dat", 7, "nu", "must be below 0.5").what(),
               "d.dat:7: field 'nu': must be below 0.5");
  EXPECT_STREQ(InputError("d.dat", 7, "", "unknown card 'FOO'").what(),
               "d.dat:7: unknown card 'FOO'");
  EXPECT_STREQ(InputError("d.dat", 0, "", "missing card MESH").what(), "d.dat: missing card MESH");
  EXPECT_STREQ(InputError("d.dat", 0, "file", "x").what(), "d.dat: field 'file': x");
  const InputError e("d.dat", 3, "E", "w");
  EXPECT_EQ(e.file(), "d.dat");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "E");
}

// One mistake per deck; the error must name file:line and the field, and say what is wrong.
struct BadDeck {
  const char* what;   // test label
  const char* text;   // the deck
  int line;           // expected line
  const char* field;  // expected field ("" = none)
  const char* reason; // expected fragment of the message
};

// Reads every value the way a stage would, so that value errors surface too.
void read_like_a_stage(const Datafile& deck) {
  for (const Card* m : deck.all("MATERIAL")) {
    m->real("E");
    m->real("nu");
    m->choice("plane", {"strain", "stress"}, "strain");
  }
  if (const Card* mesh = deck.find("MESH")) {
    mesh->integer("N", 8);
    mesh->real("R", 1);
    if (mesh->has("center")) mesh->reals("center");
  }
  for (const Card* t : deck.all("TRACTION"))
    t->reals("f");
  deck.require("MESH");
}

class DatafileBadInput : public ::testing::TestWithParam<BadDeck> {};

TEST_P(DatafileBadInput, NamesFileLineAndField) {
  const BadDeck& bad = GetParam();
  try {
    read_like_a_stage(Datafile::parse(bad.text, "decks/bad.dat"));
    FAIL() << bad.what << ": accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), "decks/bad.dat");
    EXPECT_EQ(e.line(), bad.line) << what;
    EXPECT_EQ(e.field(), bad.field) << what;
    const std::string where =
        bad.line > 0 ? "decks/bad.dat:" + std::to_string(bad.line) + ": " : "decks/bad.dat: ";
    EXPECT_EQ(what.rfind(where, 0), 0u) << what;
    if (*bad.field != '\0') {
      EXPECT_NE(what.find("field '" + std::string(bad.field) + "'"), std::string::npos) << what;
    }
    EXPECT_NE(what.find(bad.reason), std::string::npos) << what;
  }
}

const BadDeck bad_decks[] = {
    {"unknown card", "MESH generator=disc\nMESHH R=1\n", 2, "",
     "unknown card 'MESHH' (known: TITLE, MESH"},
    {"unknown field", "MESH generator=disc\nMATERIAL E=1 nu=0.3 young=2\n", 2, "young",
     "allowed: region, law, E, nu"},
    {"field without =", "MESH generator disc\n", 1, "generator", "missing '='"},
    {"value missing", "MESH generator=\n", 1, "generator", "missing value"},
    {"repeated field", "MESH generator=disc\nMATERIAL E=1 nu=0.2 e=3\n", 2, "E", "given twice"},
    {"not a number", "MESH generator=disc\n\nMATERIAL E=abc nu=0.3\n", 3, "E",
     "expected a number, got 'abc'"},
    {"number with unit", "MESH generator=disc\nMATERIAL E=210GPa nu=0.3\n", 2, "E",
     "expected a number, got '210GPa'"},
    {"nan", "MESH generator=disc\nMATERIAL E=nan nu=0.3\n", 2, "E", "finite"},
    {"inf", "MESH generator=disc\nMATERIAL E=1 nu=-inf\n", 2, "nu", "finite"},
    {"overflow", "MESH generator=disc\nMATERIAL E=1e999 nu=0.3\n", 2, "E", "out of range"},
    {"bad list item", "MESH generator=disc\nTRACTION ref=1 f=0,x\n", 2, "f",
     "expected a number, got 'x'"},
    {"empty list item", "MESH generator=disc\nTRACTION ref=1 f=0,,1\n", 2, "f", "empty item"},
    {"not an integer", "MESH generator=disc N=2.5\n", 1, "N", "expected an integer, got '2.5'"},
    {"bad choice", "MESH generator=disc\nMATERIAL E=1 nu=0.3 plane=strian\n", 2, "plane",
     "expected one of strain|stress, got 'strian'"},
    {"out of its range", "MESH generator=disc\n# steel\nMATERIAL E=1 nu=0.5\n", 3, "nu",
     "must be in (-1, 0.5), got 0.5"},
    {"below its range", "MESH generator=disc\nMATERIAL E=-2 nu=0.3\n", 2, "E",
     "must be > 0, got -2"},
    {"count out of range", "MESH generator=disc N=0\n", 1, "N", "must be in [4, 1e+08], got 0"},
    {"empty value swallowing the next field", "MESH generator=disc\nOUTPUT name= vtk=yes\n", 2,
     "name", "empty value ('vtk=yes' is the next field)"},
    {"empty value before a number field", "MESH generator=disc\nMATERIAL E= nu=0.3\n", 2, "E",
     "empty value"},
    {"empty quoted value", "MESH generator=disc\nOUTPUT name=\"\"\n", 2, "name", "empty value"},
    {"lower-case field named as the schema spells it", "MESH generator=disc r=abc\n", 1, "R",
     "expected a number"},
    {"missing required field", "MESH generator=disc\nMATERIAL nu=0.3\n", 2, "E", "missing"},
    {"unterminated quote", "MESH generator=disc\nOUTPUT name=\"abc\n", 2, "", "unterminated quote"},
    {"garbage instead of a field", "MESH generator=disc\nOUTPUT =yes\n", 2, "",
     "expected name=value"},
    {"repeated single card", "MESH generator=disc\nSOLVER method=alm\n\nsolver method=pdas\n", 4,
     "", "lines 2 and 4"},
    {"missing card", "MATERIAL E=1 nu=0.3\n", 0, "", "missing card MESH"},
    {"CR line ends: the line number counts", "MESH generator=disc\r\rMATERIAL E=x nu=0.3\r", 3, "E",
     "expected a number"},
};

INSTANTIATE_TEST_SUITE_P(Datafile, DatafileBadInput, ::testing::ValuesIn(bad_decks),
                         [](const auto& info) {
                           std::string name = info.param.what;
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
                               '_');
                           return name;
                         });

// Decks as editors save them: a byte order mark, CR LF or CR-only line ends read like LF.
TEST(Datafile, ByteOrderMarkAndEveryLineEndRead) {
  for (const std::string text :
       {"\xEF\xBB\xBFMESH generator=disc\nTITLE a\n", "MESH generator=disc\r\nTITLE a\r\n",
        "MESH generator=disc\rTITLE a\r", "MESH generator=disc\rTITLE a"}) {
    const Datafile deck = Datafile::parse(text, "d.dat");
    ASSERT_EQ(deck.cards().size(), 2u) << text;
    EXPECT_EQ(deck.cards()[0].text("generator"), "disc");
    EXPECT_EQ(deck.cards()[1].line, 2);
    EXPECT_EQ(deck.title(), "a");
  }
}

// A title that is not UTF-8 (Latin-1 from an old editor) has its bad bytes replaced, so every
// output that carries it (summary.json, VTK, DS headers) stays valid.
TEST(Datafile, TitleIsMadeValidUtf8) {
  const Datafile deck =
      Datafile::parse("TITLE caf\xe9 \xc3\xa9t\xc3\xa9\nMESH generator=disc\n", "d.dat");
  EXPECT_EQ(deck.title(), "caf\xEF\xBF\xBD \xc3\xa9t\xc3\xa9");
}

// Output names are plain file names: no folder, never hidden.
TEST(Datafile, FileNamesArePlain) {
  const Datafile deck = Datafile::parse("OUTPUT name=hertz_N256.v2\nTITLE a\n", "d.dat");
  EXPECT_EQ(deck.require("OUTPUT").file_name("name", "x"), "hertz_N256.v2");
  EXPECT_EQ(Datafile::parse("TITLE a\nMESH generator=disc\n", "d.dat")
                .require("MESH")
                .file_name("name", "fallback"),
            "fallback");
  for (const char* bad : {"../../x/pwn", "/tmp/x", "a/b", ".hidden", "..", "a b", "x:y"}) {
    const std::string text = std::string("OUTPUT name=\"") + bad + "\"\n";
    try {
      Datafile::parse(text, "d.dat").require("OUTPUT").file_name("name", "x");
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "name");
      EXPECT_NE(std::string(e.what()).find("not a plain file name"), std::string::npos) << e.what();
    }
  }
}

TEST(Datafile, UnknownCardListsTheKnownOnes) {
  try {
    Datafile::parse(good_deck, "hertz.dat");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 10);
    const std::string what = e.what();
    for (const auto& spec : card_schema())
      EXPECT_NE(what.find(spec.keyword), std::string::npos) << spec.keyword;
  }
}

TEST(Datafile, SchemaDeclaresEveryCardWithHelp) {
  std::set<std::string> keywords;
  for (const auto& spec : card_schema()) {
    EXPECT_TRUE(keywords.insert(spec.keyword).second) << spec.keyword;
    EXPECT_GT(std::strlen(spec.help), 0u) << spec.keyword;
    std::set<std::string> names;
    for (const auto& field : spec.fields) {
      std::string lower = field.name;
      for (auto& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      EXPECT_TRUE(names.insert(lower).second) << spec.keyword << " " << field.name;
      EXPECT_GT(std::strlen(field.help), 0u) << spec.keyword << " " << field.name;
    }
  }
  // The cards every stage of the static chain reads are declared.
  for (const char* keyword : {"TITLE", "MESH", "MATERIAL", "DIRICHLET", "TRACTION", "PRESSURE",
                              "BODYFORCE", "CONTACT", "SOLVER", "OUTPUT"})
    EXPECT_TRUE(keywords.count(keyword)) << keyword;
  // Repeatable cards can appear twice; single cards cannot.
  EXPECT_NO_THROW(Datafile::parse("DIRICHLET ref=1 ux=0\nDIRICHLET ref=2 uy=0\n", "d.dat"));
  EXPECT_THROW(Datafile::parse("OUTPUT vtk=no\nOUTPUT vtk=yes\n", "d.dat"), InputError);
  // Every field of the brief is accepted.
  EXPECT_NO_THROW(Datafile::parse(
      "MESH generator=ring file=a.msh R=1 N=2 centre=0,0 r_in=1 r_out=2 layers=3 lx=1 ly=1 nx=2 "
      "ny=2 refs=1,2 grading=1 gamma1_above=0.9 gamma3_below=0.1\n"
      "MATERIAL region=1 law=hooke E=1 nu=0 plane=stress thickness=1 rho=1\n"
      "DIRICHLET ref=1 ux=0 uy=0\nTRACTION ref=1 f=0,1\nPRESSURE ref=1 p=2\n"
      "BODYFORCE region=1 f=0,-1\n"
      "CONTACT ref=2 obstacle=plane point=0,0 normal=0,-1 law=signorini gap=0\n"
      "SOLVER linear=mumps method=alm r=1 gamma=1 c=1 eps=1e-10 maxit=50\n"
      "OUTPUT vtk=yes name=x\n",
      "all.dat"));
}

} // namespace
} // namespace sig

namespace sig {
namespace {

// One table of ranges serves the deck and the DS readers: the same words either way.
TEST(Ranges, OneRangeForTheDeckAndTheFiles) {
  ASSERT_NE(field_range("material", "NU"), nullptr);
  EXPECT_EQ(field_range("MATERIAL", "nu")->text(), "in (-1, 0.5)");
  EXPECT_EQ(field_range("MATERIAL", "E")->text(), "> 0");
  EXPECT_EQ(field_range("MATERIAL", "rho")->text(), ">= 0");
  EXPECT_EQ(field_range("TRACTION", "f"), nullptr);
  EXPECT_NO_THROW(verify_in_range(0.3, "MATERIAL", "nu", "case.mili", "poisson", 1));
  for (double bad : {0.5, -1.0, std::nan("")}) {
    try {
      verify_in_range(bad, "MATERIAL", "nu", "out/case.mili", "poisson", 2);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("out/case.mili: array 'poisson', row 2: "),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("is not in (-1, 0.5) (the range of MATERIAL nu=)"),
                std::string::npos)
          << e.what();
    }
  }
  // Every field with a range is a field of the schema (a misspelt line would check nothing).
  for (const auto& [keyword, field] : fields_with_ranges()) {
    bool found = false;
    for (const auto& spec : card_schema())
      for (const auto& f : spec.fields)
        found = found || (keyword == spec.keyword && field == f.name);
    EXPECT_TRUE(found) << keyword << " " << field;
  }
}

} // namespace
} // namespace sig
