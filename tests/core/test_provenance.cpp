// The files of a case belong together: a DS records the inputs it was built from, and inside a
// stage a DS of the case that disagrees with another input is refused, naming both files.
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/provenance.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>

namespace sig {
namespace {

using sig::testing::ScratchFolder;

Ds small(const std::string& kind, double value) {
  Ds ds(kind, "t", "test");
  ds.put_scalar("value", value);
  return ds;
}

// Opens a case on `folder` for the test, closed whatever happens.
struct CaseScope {
  explicit CaseScope(const std::filesystem::path& folder) { open_case(folder); }
  ~CaseScope() { close_case(); }
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Provenance, ADsRecordsItsInputsAndTheirsTransitively) {
  ScratchFolder dir;
  const auto mili = dir / "case.mili", tae = dir / "case.tae", b = dir / "case.b";
  write_ds(mili, small("MILI", 1)); // outside a stage: no provenance
  EXPECT_FALSE(read_ds(mili).has("provenance"));
  {
    const CaseScope scope(dir.path());
    note_case_input("NOPO", dir / "case.nopo", 0x1234, {});
    const Ds m = read_ds(mili, "MILI");
    write_ds(tae, small("TAE", 2));
  }
  const Ds t = read_ds(tae, "TAE");
  const auto entries = parse_provenance(t.text("provenance"), t.source).inputs;
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].kind, "NOPO");
  EXPECT_EQ(entries[0].fingerprint, 0x1234u);
  EXPECT_EQ(entries[1].kind, "MILI");
  EXPECT_EQ(entries[1].fingerprint, read_ds(mili).fingerprint);
  EXPECT_EQ(entries[1].file, mili.string());
  {
    const CaseScope scope(dir.path());
    read_ds(tae, "TAE");
    write_ds(b, small("B", 3));
  }
  // B was built from TAE, and through it from MILI and NOPO.
  const auto b_entries = parse_provenance(read_ds(b).text("provenance"), b.string()).inputs;
  std::vector<std::string> kinds;
  for (const auto& e : b_entries)
    kinds.push_back(e.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"TAE", "NOPO", "MILI"}));
}

TEST(Provenance, AForeignFileIsRefusedNamingBothFiles) {
  ScratchFolder dir;
  const auto mili = dir / "case.mili", tae = dir / "case.tae";
  write_ds(mili, small("MILI", 1));
  {
    const CaseScope scope(dir.path());
    read_ds(mili, "MILI");
    write_ds(tae, small("TAE", 2));
  }
  write_ds(mili, small("MILI", 7)); // another case's laws
  const CaseScope scope(dir.path());
  read_ds(tae, "TAE");
  const std::string message = error_of([&] { read_ds(mili, "MILI"); });
  EXPECT_NE(message.find("do not belong together"), std::string::npos) << message;
  EXPECT_NE(message.find(tae.string() + " was built from the MILI " + mili.string()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(mili.string() + " is the MILI with fingerprint"), std::string::npos)
      << message;
}

TEST(Provenance, TwoRecordsOfOneKindMustAgree) {
  ScratchFolder dir;
  const auto cont = dir / "case.cont", tae = dir / "case.tae";
  {
    const CaseScope scope(dir.path());
    note_case_input("NOPO", dir / "case.nopo", 1, {});
    write_ds(cont, small("CONT", 1));
  }
  {
    const CaseScope scope(dir.path());
    note_case_input("NOPO", dir / "case.nopo", 2, {}); // another mesh
    write_ds(tae, small("TAE", 1));
  }
  const CaseScope scope(dir.path());
  read_ds(cont, "CONT");
  const std::string message = error_of([&] { read_ds(tae, "TAE"); });
  EXPECT_NE(message.find(cont.string() + " was built from the NOPO"), std::string::npos) << message;
  EXPECT_NE(message.find(tae.string() + " was built from the NOPO"), std::string::npos) << message;
}

// Files outside the case's folder (a reference solution) are no inputs of the case; outside a
// stage nothing is checked.
TEST(Provenance, OnlyTheCaseFolderCounts) {
  ScratchFolder dir;
  std::filesystem::create_directories(dir / "case");
  const auto mine = dir / "case" / "case.b", reference = dir / "case.b";
  write_ds(mine, small("B", 1));
  write_ds(reference, small("B", 2));
  const CaseScope scope(dir / "case");
  read_ds(mine, "B");
  EXPECT_NO_THROW(read_ds(reference, "B"));
  close_case();
  EXPECT_NO_THROW(read_ds(mine, "B"));
}

TEST(Provenance, TextRoundTripsAndBadLinesAreRefused) {
  const Provenance entries{
      {{"NOPO", 0xfedcba9876543210ull, "out/a b/case.nopo"}, {"TAE", 7, "case.tae"}},
      {{"FRICTION", 0x0123456789abcdefull, "ref=3 law=coulomb mu=0.4"}}};
  const auto back = parse_provenance(provenance_text(entries), "x");
  ASSERT_EQ(back.inputs.size(), 2u);
  EXPECT_EQ(back.inputs[0].fingerprint, entries.inputs[0].fingerprint);
  EXPECT_EQ(back.inputs[0].file, "out/a b/case.nopo");
  EXPECT_EQ(back.inputs[1].kind, "TAE");
  ASSERT_EQ(back.cards.size(), 1u);
  EXPECT_EQ(back.cards[0].keyword, "FRICTION");
  EXPECT_EQ(back.cards[0].fingerprint, 0x0123456789abcdefull);
  EXPECT_EQ(back.cards[0].values, "ref=3 law=coulomb mu=0.4");
  for (const char* bad :
       {"NOPO 12 case.nopo", "TOOLONG 0000000000000007 f", "NOPO 000000000000000g f",
        "NOPO 0000000000000007", "", "CARD MESH 0000000000000007", "CARD MESH 7 N=16", "CARD",
        "CARD  0000000000000007 N=16"})
    EXPECT_NE(error_of([&] { parse_provenance(std::string(bad) + "\n", "x.ds"); }).find("x.ds"),
              std::string::npos)
        << bad;
}

// The deck: a stage's files record the cards they depend on, their inputs' too.
const char* const deck_text = "TITLE t\nMESH generator=square lx=1 nx=2\nMATERIAL E=1 nu=0.3\n"
                              "CONTACT ref=1 obstacle=plane point=0,0 normal=0,1\n"
                              "FRICTION ref=1 law=coulomb mu=0.4\nSOLVER method=pdas\n";

Datafile deck_with(const std::string& from, const std::string& to) {
  std::string text = deck_text;
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  return Datafile::parse(text, "d.dat");
}

struct StageCase {
  StageCase(const std::filesystem::path& folder, const Datafile& deck, const std::string& stage) {
    open_case(folder, deck, stage);
  }
  ~StageCase() { close_case(); }
};

std::vector<std::string> keywords(const Provenance& provenance) {
  std::vector<std::string> found;
  for (const CardRecord& card : provenance.cards)
    found.push_back(card.keyword);
  return found;
}

TEST(Provenance, ADsRecordsTheCardsOfItsStageAndOfItsInputs) {
  ScratchFolder dir;
  const Datafile deck = deck_with("", "");
  {
    const StageCase stage(dir.path(), deck, "contact");
    write_ds(dir / "case.cont", small("CONT", 1));
  }
  const Provenance cont = parse_provenance(read_ds(dir / "case.cont").text("provenance"), "cont");
  EXPECT_EQ(keywords(cont), (std::vector<std::string>{"CONTACT", "FRICTION"}));
  EXPECT_EQ(cont.cards[1].values, "ref=1 law=coulomb mu=0.4 bound=normal of=slip");
  {
    const StageCase stage(dir.path(), deck, "solve");
    read_ds(dir / "case.cont", "CONT");
    write_ds(dir / "case.b", small("B", 2));
  }
  const Provenance b = parse_provenance(read_ds(dir / "case.b").text("provenance"), "b");
  EXPECT_EQ(keywords(b), (std::vector<std::string>{"CONTACT", "FRICTION", "SOLVER", "LOADSTEPS",
                                                   "CONVEXIFICATION", "INITIAL", "TRACTION",
                                                   "PRESSURE", "BODYFORCE", "DIRICHLET"}));
  EXPECT_EQ(b.inputs.size(), 1u); // CONT
}

TEST(Provenance, AStaleOrForeignDsIsRefusedNamingTheCardAndTheStageToRerun) {
  ScratchFolder dir;
  {
    const StageCase stage(dir.path(), deck_with("", ""), "contact");
    write_ds(dir / "case.cont", small("CONT", 1));
  }
  {
    const StageCase stage(dir.path(), deck_with("mu=0.4", "mu=0.05"), "solve");
    const std::string message = error_of([&] { read_ds(dir / "case.cont", "CONT"); });
    EXPECT_NE(message.find((dir / "case.cont").string() + " was made with FRICTION mu=0.4, but "
                                                          "d.dat:5 now says FRICTION mu=0.05"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("rerun sig-contact and the stages after it"), std::string::npos)
        << message;
  }
  // A card the file does not depend on may change; a comment changes nothing.
  const StageCase stage(dir.path(), deck_with("E=1 nu=0.3\n", "E=2 nu=0.3 # stiffer\n"), "solve");
  EXPECT_NO_THROW(read_ds(dir / "case.cont", "CONT"));
}

TEST(Provenance, ADsRecordingNoDeckIsRefusedInAStage) {
  ScratchFolder dir;
  write_ds(dir / "case.mili", small("MILI", 1)); // outside a stage: no record
  const StageCase stage(dir.path(), deck_with("", ""), "assemble");
  const std::string message = error_of([&] { read_ds(dir / "case.mili", "MILI"); });
  EXPECT_NE(message.find("case.mili records no deck it was made from"), std::string::npos)
      << message;
  EXPECT_NE(message.find("rerun sig-material"), std::string::npos) << message;
}

// A file that is not a DS keeps its record beside it; it must be there and describe the file.
TEST(Provenance, TheRecordBesideAFileDescribesIt) {
  ScratchFolder dir;
  const auto nopo = dir / "case.nopo";
  {
    const StageCase stage(dir.path(), deck_with("", ""), "mesh");
    write_provenance_beside(nopo, "NOPO", 0x1234, "t", "sig-mesh");
  }
  const Provenance record =
      parse_provenance(read_ds(provenance_beside(nopo)).text("provenance"), "prov");
  EXPECT_EQ(keywords(record), (std::vector<std::string>{"MESH"}));
  {
    const StageCase stage(dir.path(), deck_with("", ""), "material");
    EXPECT_NO_THROW(note_case_file("NOPO", nopo, 0x1234));
  }
  {
    const StageCase stage(dir.path(), deck_with("", ""), "material");
    const std::string message = error_of([&] { note_case_file("NOPO", nopo, 0x5678); });
    EXPECT_NE(message.find(nopo.string() + " is not the NOPO that"), std::string::npos) << message;
  }
  {
    const StageCase stage(dir.path(), deck_with("nx=2", "nx=4"), "material");
    const std::string message = error_of([&] { note_case_file("NOPO", nopo, 0x1234); });
    EXPECT_NE(message.find("was made with MESH nx=2, but d.dat:2 now says MESH nx=4"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("rerun sig-mesh"), std::string::npos) << message;
  }
  std::filesystem::remove(provenance_beside(nopo));
  const StageCase stage(dir.path(), deck_with("", ""), "material");
  const std::string message = error_of([&] { note_case_file("NOPO", nopo, 0x1234); });
  EXPECT_NE(message.find(nopo.string() + " has no record of the deck it was made from"),
            std::string::npos)
      << message;
}

} // namespace
} // namespace sig
