// Which stages of a case are stale for a deck (core/stale.hpp): a case built stage by stage as
// the stages build it (each reads the files of the stages before it and writes its own, which
// records them and the deck's cards), then the deck or a file changed.
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/provenance.hpp"
#include "core/stale.hpp"
#include "scratch_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace sig {
namespace {

using sig::testing::ScratchFolder;
namespace fs = std::filesystem;

const char* const deck_text = "TITLE t\nMESH generator=square lx=1 nx=2\nMATERIAL E=1 nu=0.3\n"
                              "DIRICHLET ref=1 ux=0 uy=0\n"
                              "CONTACT ref=3 obstacle=plane point=0,0 normal=0,1\n"
                              "FRICTION ref=3 law=coulomb mu=0.4\nSOLVER method=pdas\n";

// The mesh stands for a NOPO file: its bytes, and their hash as its fingerprint.
std::uint64_t mesh_fingerprint(const fs::path& path) {
  const std::string bytes = testing::slurp(path);
  return fnv1a64(bytes.data(), bytes.size());
}

class Stale : public ::testing::Test {
protected:
  Datafile deck(const std::string& from = "", const std::string& to = "") const {
    std::string text = deck_text;
    if (!from.empty()) text.replace(text.find(from), from.size(), to);
    return Datafile::parse(text, "d.dat");
  }
  // Runs `stage` on the case: reads `inputs` (the mesh through its record), writes its output.
  void run(const std::string& stage, const Datafile& deck, const std::vector<std::string>& inputs,
           const std::string& output, const std::string& kind) {
    open_case(dir_, deck, stage);
    try {
      for (const std::string& input : inputs) {
        if (input == "nopo")
          note_case_file("NOPO", dir_ / "case.nopo", mesh_fingerprint(dir_ / "case.nopo"));
        else
          read_ds(dir_ / ("case." + input));
      }
      if (kind == "NOPO") {
        std::ofstream(dir_ / "case.nopo") << "mesh of " << deck.cards()[1].fields[2].second;
        write_provenance_beside(dir_ / "case.nopo", "NOPO", mesh_fingerprint(dir_ / "case.nopo"),
                                "t", "sig-mesh");
      } else {
        Ds ds(kind, "t", "sig-" + stage);
        ds.put_scalar("value", ++runs_); // every run writes another file
        if (kind == "POST") ds.put_text("files", "t.vtu\n");
        write_ds(dir_ / ("case." + output), ds);
        if (kind == "POST") std::ofstream(dir_ / "t.vtu") << "vtu";
      }
    } catch (...) {
      close_case();
      throw;
    }
    close_case();
  }
  void run_chain(const Datafile& deck) {
    run("mesh", deck, {}, "nopo", "NOPO");
    run("material", deck, {"nopo"}, "mili", "MILI");
    run("contact", deck, {"nopo"}, "cont", "CONT");
    run("assemble", deck, {"nopo", "mili"}, "tae", "TAE");
    run("solve", deck, {"tae", "cont", "nopo", "mili"}, "b", "B");
    run("post", deck, {"nopo", "mili", "b", "cont", "tae"}, "post", "POST");
  }
  std::string stale(const Datafile& deck) const {
    std::string names;
    for (const StaleStage& s : stale_stages(deck, dir_, mesh_fingerprint))
      names += (names.empty() ? "" : " ") + s.stage;
    return names;
  }
  std::string why(const Datafile& deck, const std::string& stage) const {
    for (const StaleStage& s : stale_stages(deck, dir_, mesh_fingerprint))
      if (s.stage == stage) return s.why;
    return "";
  }
  const ScratchFolder scratch_;
  const fs::path dir_ = scratch_.path();
  int runs_ = 0;
};

TEST_F(Stale, AnEmptyCaseIsStaleThroughoutAndABuiltOneUpToDate) {
  EXPECT_EQ(stale(deck()), "mesh material contact assemble solve post");
  EXPECT_NE(why(deck(), "mesh").find("case.nopo does not exist"), std::string::npos);
  run_chain(deck());
  EXPECT_EQ(stale(deck()), "");
  // Text that gives the same values.
  EXPECT_EQ(stale(deck("MATERIAL E=1 nu=0.3", "# steel\nmaterial nu=0.30 E=1e0 plane=strain")), "");
}

TEST_F(Stale, ACardMakesStaleTheStagesThatReadItAndTheStagesAfterThem) {
  run_chain(deck());
  EXPECT_EQ(stale(deck("mu=0.4", "mu=0.05")), "contact solve post");
  EXPECT_EQ(why(deck("mu=0.4", "mu=0.05"), "contact"),
            (dir_ / "case.cont").string() +
                " was made with FRICTION mu=0.4, but d.dat:6 now says FRICTION mu=0.05");
  EXPECT_EQ(stale(deck("E=1", "E=2")), "material assemble solve post");
  EXPECT_EQ(stale(deck("ux=0 uy=0", "ux=0")), "assemble solve post");
  EXPECT_EQ(stale(deck("method=pdas", "method=alm")), "solve post");
  EXPECT_EQ(stale(deck("nx=2", "nx=4")), "mesh material contact assemble solve post");
  EXPECT_EQ(stale(deck("TITLE t\n", "TITLE t\nOUTPUT vtk=no\n")), "post");
  EXPECT_EQ(stale(deck("TITLE t\n", "TITLE another name\n")), "post");
}

TEST_F(Stale, AFileRerunAloneOrReplacedMakesStaleWhatWasBuiltFromIt) {
  run_chain(deck());
  run("material", deck(), {"nopo"}, "mili", "MILI"); // rerun alone: another case.mili
  EXPECT_EQ(stale(deck()), "assemble solve post");
  EXPECT_NE(why(deck(), "assemble").find("case.mili changed since"), std::string::npos)
      << why(deck(), "assemble");
  run_chain(deck());
  std::ofstream(dir_ / "case.nopo", std::ios::app) << " moved"; // not the mesh of its record
  EXPECT_EQ(stale(deck()), "mesh material contact assemble solve post");
  EXPECT_NE(why(deck(), "mesh").find("is not the file"), std::string::npos);
  run_chain(deck());
  fs::remove(dir_ / "t.vtu"); // an output of sig-post gone
  EXPECT_EQ(stale(deck()), "post");
  run_chain(deck());
  fs::remove(dir_ / "case.cont");
  EXPECT_EQ(stale(deck()), "contact solve post");
}

TEST_F(Stale, AFileOfAnotherDeckCopiedInIsStale) {
  run_chain(deck());
  const ScratchFolder other;
  fs::copy(dir_, other.path());
  // The other case, made from mu = 0.05; its case.cont copied into this one.
  open_case(other.path(), deck("mu=0.4", "mu=0.05"), "contact");
  Ds cont("CONT", "t", "sig-contact");
  cont.put_scalar("value", 99);
  note_case_file("NOPO", other / "case.nopo", mesh_fingerprint(other / "case.nopo"));
  write_ds(other / "case.cont", cont);
  close_case();
  fs::copy_file(other / "case.cont", dir_ / "case.cont", fs::copy_options::overwrite_existing);
  EXPECT_EQ(stale(deck()), "contact solve post");
}

} // namespace
} // namespace sig
