// What a file records of the deck it was made from: the values of the cards, not their text.
// Every way of writing the same values gives the same fingerprint; every other value gives
// another one, and the words for the change name the field, its old and new values and the line.
#include "core/card_fingerprint.hpp"
#include "core/datafile.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace sig {
namespace {

using sig::testing::ScratchFolder;

const char* const base = "TITLE a block\n"
                         "MESH generator=rectangle lx=4 ly=1 nx=4 ny=2\n"
                         "MATERIAL region=1 law=hooke E=200 nu=0.3\n"
                         "MATERIAL region=2 law=hooke E=100 nu=0.25\n"
                         "DIRICHLET ref=1 ux=0 uy=0\n"
                         "DIRICHLET ref=4 uy=-0.01\n"
                         "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n"
                         "FRICTION ref=3 law=coulomb mu=0.4\n"
                         "SOLVER method=pdas eps=1e-8\n";

const char* const keywords[] = {"MESH",    "MATERIAL", "DIRICHLET", "CONTACT", "FRICTION",
                                "SOLVER",  "TIME",     "OUTPUT",    "INITIAL", "TRACTION",
                                "COMPARE", "MEMORY",   "LOADSTEPS"};

std::uint64_t fingerprint(const std::string& deck, const std::string& keyword) {
  return card_record(Datafile::parse(deck, "d.dat"), keyword).fingerprint;
}

// The same values, written otherwise: every card keyword keeps its fingerprint.
TEST(CardFingerprint, ValuesNotText) {
  const std::vector<std::pair<const char*, std::string>> same = {
      {"comments, blank lines and spacing",
       "# a comment\nTITLE a block   # trailing\n\n"
       "MESH   generator=rectangle  lx = 4 ly=1 nx=4 ny=2\n"
       "MATERIAL region=1 law=hooke E=200 nu=0.3 # steel\n"
       "MATERIAL region=2 law=hooke E=100 nu=0.25\n"
       "DIRICHLET ref=1 ux=0 uy=0\nDIRICHLET ref=4 uy=-0.01\n"
       "CONTACT ref=3 obstacle=plane point=0, 0 normal=0,1\n"
       "\t FRICTION ref=3 law=coulomb mu=0.4\nSOLVER method=pdas eps=1e-8\n"},
      {"the cards reordered, MATERIAL by region too",
       "SOLVER method=pdas eps=1e-8\nFRICTION ref=3 law=coulomb mu=0.4\n"
       "MATERIAL region=2 law=hooke E=100 nu=0.25\nTITLE a block\n"
       "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n"
       "DIRICHLET ref=1 ux=0 uy=0\nDIRICHLET ref=4 uy=-0.01\n"
       "MATERIAL region=1 law=hooke E=200 nu=0.3\n"
       "MESH generator=rectangle lx=4 ly=1 nx=4 ny=2\n"},
      {"fields reordered, keywords, names and choices in other cases",
       "title a block\nmesh NY=2 nx=4 LY=1 lx=4 generator=Rectangle\n"
       "Material nu=0.3 E=200 law=HOOKE region=1\nMATERIAL region=2 law=hooke E=100 nu=0.25\n"
       "DIRICHLET uy=0 ux=0 ref=1\nDIRICHLET ref=4 uy=-0.01\n"
       "CONTACT normal=0,1 point=0,0 obstacle=Plane ref=3\n"
       "FRICTION mu=0.4 law=Coulomb ref=3\nSOLVER eps=1e-8 method=PDAS\n"},
      {"numbers spelt otherwise",
       "TITLE a block\nMESH generator=rectangle lx=4.0 ly=+1 nx=4 ny=2\n"
       "MATERIAL region=1 law=hooke E=2e2 nu=0.30\nMATERIAL region=2 law=hooke E=100. nu=.25\n"
       "DIRICHLET ref=1 ux=-0 uy=0.0\nDIRICHLET ref=4 uy=-1e-2\n"
       "CONTACT ref=3 obstacle=plane point=-0,0e0 normal=0.0,1.00\n"
       "FRICTION ref=3 law=coulomb mu=4e-1\nSOLVER method=pdas eps=0.00000001\n"},
      {"defaults spelt out",
       "TITLE another title: a name, no value\n"
       "MESH generator=rectangle lx=4 ly=1 nx=4 ny=2 refs=3,4,2,1 pattern=alternating grading=0\n"
       "MATERIAL region=1 law=hooke E=200 nu=0.3 plane=strain thickness=1 rho=0\n"
       "MATERIAL region=2 law=hooke E=100 nu=0.25 eta1=0\n"
       "DIRICHLET ref=1 ux=0 uy=0\nDIRICHLET ref=4 uy=-0.01\n"
       "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini g=0\n"
       "FRICTION ref=3 law=coulomb mu=0.4 bound=normal\n"
       "SOLVER method=pdas eps=1e-8 linear=cholmod r=100 gamma=100 c=100 search=auto\n"},
  };
  for (const auto& [what, deck] : same)
    for (const char* keyword : keywords)
      EXPECT_EQ(fingerprint(deck, keyword), fingerprint(base, keyword)) << what << ": " << keyword;
}

// Another value of one card changes that card's fingerprint and no other's.
// An old spelling is the field it was renamed to: a deck rewritten with the new names (MESH
// centre=, CONTACT g=) leaves its files up to date, and the old name cannot hide a changed value.
TEST(CardFingerprint, AnOldSpellingIsTheNewField) {
  const std::string ring = "MESH generator=ring r_in=9 r_out=10 N=16 layers=2 ";
  EXPECT_EQ(fingerprint(ring + "center=0,10\n", "MESH"),
            fingerprint(ring + "centre=0,10\n", "MESH"));
  EXPECT_NE(fingerprint(ring + "center=0,10\n", "MESH"),
            fingerprint(ring + "centre=0,0\n", "MESH"));
  EXPECT_NE(fingerprint(ring + "center=0,10\n", "MESH"), fingerprint(ring, "MESH"));
  const std::string contact = "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1 law=signorini ";
  EXPECT_EQ(fingerprint(contact + "gap=0.1\n", "CONTACT"),
            fingerprint(contact + "g=0.1\n", "CONTACT"));
  EXPECT_NE(fingerprint(contact + "gap=0.1\n", "CONTACT"), fingerprint(contact, "CONTACT"));
}

TEST(CardFingerprint, AnotherValueIsAnotherFingerprint) {
  const std::vector<std::tuple<const char*, const char*, const char*>> changes = {
      {"mu=0.4", "mu=0.05", "FRICTION"},
      {"law=coulomb mu=0.4", "law=tresca threshold=0.1", "FRICTION"},
      {"point=0,0", "point=0,-0.001", "CONTACT"},
      {"E=200", "E=210", "MATERIAL"},
      {"uy=-0.01", "uy=-0.02", "DIRICHLET"},
      {"nx=4", "nx=8", "MESH"},
      {"method=pdas", "method=alm", "SOLVER"},
      {"SOLVER method=pdas eps=1e-8\n", "SOLVER method=pdas eps=1e-8\nTIME T=1 k=0.1\n", "TIME"},
      {"FRICTION ref=3 law=coulomb mu=0.4\n", "", "FRICTION"},
  };
  const std::string deck = base;
  for (const auto& [from, to, keyword] : changes) {
    std::string changed = deck;
    changed.replace(changed.find(from), std::string(from).size(), to);
    for (const char* other : keywords)
      if (std::string(other) == keyword)
        EXPECT_NE(fingerprint(changed, other), fingerprint(deck, other)) << from << " -> " << to;
      else
        EXPECT_EQ(fingerprint(changed, other), fingerprint(deck, other))
            << from << " -> " << to << ": " << other;
  }
}

// DIRICHLET and INITIAL: a later card overrides an earlier one on shared nodes, so their order
// is a value; OUTPUT name= is a file name, whose case is a value.
TEST(CardFingerprint, OrderWhereALaterCardWinsAndTheCaseOfAFileName) {
  const std::string a = "DIRICHLET ref=1 ux=0\nDIRICHLET ref=2 ux=1\nINITIAL u=1,0\nINITIAL "
                        "u=0,1 region=2\nMATERIAL region=1 E=1 nu=0\nMATERIAL region=2 E=2 nu=0\n";
  const std::string b = "DIRICHLET ref=2 ux=1\nDIRICHLET ref=1 ux=0\nINITIAL u=0,1 region=2\n"
                        "INITIAL u=1,0\nMATERIAL region=2 E=2 nu=0\nMATERIAL region=1 E=1 nu=0\n";
  EXPECT_NE(fingerprint(a, "DIRICHLET"), fingerprint(b, "DIRICHLET"));
  EXPECT_NE(fingerprint(a, "INITIAL"), fingerprint(b, "INITIAL"));
  EXPECT_EQ(fingerprint(a, "MATERIAL"), fingerprint(b, "MATERIAL"));
  EXPECT_NE(fingerprint("OUTPUT name=Hertz\n", "OUTPUT"),
            fingerprint("OUTPUT name=hertz\n", "OUTPUT"));
  EXPECT_EQ(fingerprint("OUTPUT vtk=YES\n", "OUTPUT"), fingerprint("OUTPUT\n", "OUTPUT"));
  EXPECT_NE(fingerprint("TITLE a b\n", "TITLE"), fingerprint("TITLE a  b\n", "TITLE"));
  EXPECT_EQ(fingerprint("TITLE a b # c\n", "TITLE"), fingerprint("TITLE \"a b\"\n", "TITLE"));
}

// A mesh file is its contents: the same mesh under another name is no change, the file
// rewritten in place is one.
TEST(CardFingerprint, AMeshFileIsItsContents) {
  ScratchFolder dir;
  std::ofstream(dir / "a.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  std::ofstream(dir / "b.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const auto record = [&](const std::string& file) {
    const std::string deck = "MESH file=" + file + "\n";
    return card_record(Datafile::parse(deck, (dir / "d.dat").string()), "MESH");
  };
  const CardRecord a = record("a.msh");
  EXPECT_EQ(a.fingerprint, record("b.msh").fingerprint);
  EXPECT_EQ(a.fingerprint, record((dir / "a.msh").string()).fingerprint);
  EXPECT_NE(a.values.find("file=content:"), std::string::npos) << a.values;
  std::ofstream(dir / "a.msh", std::ios::app) << "$Nodes\n0\n$EndNodes\n";
  EXPECT_NE(a.fingerprint, record("a.msh").fingerprint);
  EXPECT_NE(a.fingerprint, record("missing.msh").fingerprint);
}

// The words for a change: the card, the fields that differ with both values, the deck's line.
TEST(CardFingerprint, TheChangeNamesTheFieldTheValuesAndTheLine) {
  const Datafile before = Datafile::parse(base, "d.dat");
  const auto change = [&](const char* keyword, const std::string& from, const std::string& to) {
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    return card_change(card_record(before, keyword), Datafile::parse(text, "e.dat"));
  };
  EXPECT_EQ(card_change(card_record(before, "FRICTION"), before), "");
  EXPECT_EQ(change("FRICTION", "mu=0.4", "mu=0.05"),
            "with FRICTION mu=0.4, but e.dat:8 now says FRICTION mu=0.05");
  EXPECT_EQ(change("FRICTION", "law=coulomb mu=0.4", "law=tresca threshold=0.1"),
            "with FRICTION law=coulomb mu=0.4 threshold=(not given), but e.dat:8 now says "
            "FRICTION law=tresca mu=(not given) threshold=0.1");
  // A repeatable card says which one it is.
  EXPECT_EQ(change("MATERIAL", "E=100", "E=120"),
            "with MATERIAL region=2 E=100, but e.dat:4 now says MATERIAL region=2 E=120");
  EXPECT_EQ(change("DIRICHLET", "DIRICHLET ref=4 uy=-0.01\n", ""),
            "with 2 DIRICHLET cards, but e.dat now has 1 (line 5)");
  EXPECT_EQ(change("FRICTION", "FRICTION ref=3 law=coulomb mu=0.4\n", ""),
            "with FRICTION ref=3 law=coulomb mu=0.4 bound=normal of=slip, but e.dat has no "
            "FRICTION card now");
  EXPECT_EQ(change("TITLE", "TITLE a block", "TITLE a|50% block"),
            "with TITLE text=a block, but e.dat:1 now says TITLE text=a|50% block");
  EXPECT_EQ(change("TIME", "SOLVER", "TIME T=1 k=0.5\nSOLVER"),
            "without a TIME card, but e.dat:9 now has TIME T=1 k=0.5 output_every=1 "
            "mass=consistent stress=gonzalez");
}

} // namespace
} // namespace sig
