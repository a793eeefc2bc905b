// What stage mains share: the command line, the output folder, the catch-all, the log lines.
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_guard.hpp"
#include "scratch_folder.hpp"

#include <cctype>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <gtest/gtest.h>
#include <stdexcept>
#include <thread>

namespace sig {
namespace {

using sig::testing::ScratchFolder;

StageArgs parse(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  return parse_stage_args(static_cast<int>(argv.size()), argv.data(), {.name = "mesh"});
}

// The stages read their datafile with their arguments: a small deck at `path`.
void write_deck(const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << "# a deck\nMESH generator=square lx=1 nx=2\n";
}

// Runs the test's body in `dir` (the stages take relative paths from the working folder).
struct WorkingFolder {
  explicit WorkingFolder(const std::filesystem::path& dir) { std::filesystem::current_path(dir); }
  ~WorkingFolder() { std::filesystem::current_path(cwd); }
  std::filesystem::path cwd = std::filesystem::current_path();
};

TEST(Stage, ExplicitOutputFolderIsCreated) {
  ScratchFolder dir;
  const WorkingFolder here(dir.path());
  write_deck("decks/hertz.dat");
  write_deck("x.dat");
  const auto out = dir / "runs" / "n8";
  const StageArgs args = parse({"sig-mesh", "decks/hertz.dat", "-o", out.string()});
  EXPECT_EQ(args.datafile, std::filesystem::path("decks/hertz.dat"));
  EXPECT_EQ(args.outdir, out);
  EXPECT_TRUE(std::filesystem::is_directory(out));
  EXPECT_EQ(args.ds_path("nopo"), out / "case.nopo");
  ASSERT_EQ(args.deck.cards().size(), 1u); // the datafile, read
  EXPECT_EQ(args.deck.cards()[0].keyword, "MESH");
  // -o may come first.
  EXPECT_EQ(parse({"sig-mesh", "-o", out.string(), "x.dat"}).outdir, out);
}

TEST(Stage, AMissingDatafileIsAnErrorNamingIt) {
  ScratchFolder dir;
  const WorkingFolder here(dir.path());
  try {
    parse({"sig-mesh", "nowhere.dat", "-o", "out"});
    ADD_FAILURE() << "nowhere.dat accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere.dat"), std::string::npos) << e.what();
  }
}

TEST(Stage, DefaultOutputFolderIsOutSlashStem) {
  ScratchFolder dir;
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  write_deck("datafiles/hertz_n8.dat");
  StageArgs args;
  EXPECT_NO_THROW(args = parse({"sig-mesh", "datafiles/hertz_n8.dat"}));
  const bool created = std::filesystem::is_directory(dir / "out" / "hertz_n8");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(args.outdir, std::filesystem::path("out/hertz_n8"));
  EXPECT_TRUE(created);
  EXPECT_EQ(args.ds_path("tae"), std::filesystem::path("out/hertz_n8/case.tae"));
}

TEST(Stage, BadCommandLinesGiveTheUsage) {
  const std::vector<std::vector<std::string>> bad = {{"sig-mesh"},
                                                     {"sig-mesh", "a.dat", "b.dat"},
                                                     {"sig-mesh", "a.dat", "-o"},
                                                     {"sig-mesh", "-x", "a.dat"},
                                                     {"sig-mesh", "-o", "out"}};
  for (const auto& words : bad) {
    try {
      parse(words);
      ADD_FAILURE() << words.size();
    } catch (const Error& e) {
      EXPECT_STREQ(e.what(), "usage: sig-mesh DATAFILE [-o OUTDIR] [--time-limit SECONDS] "
                             "(--help: what it reads, writes and the cards it uses)");
    }
  }
}

TEST(Stage, RunStageTurnsExceptionsIntoExitCodeOne) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run_stage("solve", [] {}), 0);
  EXPECT_EQ(run_stage("solve", [] { throw InputError("d.dat", 3, "r", "must be positive"); }), 1);
  EXPECT_EQ(run_stage("sig-post", [] { throw std::runtime_error("disk full"); }), 1);
  EXPECT_EQ(run_stage("mesh", [] { throw 42; }), 1);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("sig-solve: error: d.dat:3: field 'r': must be positive\n"), std::string::npos)
      << err;
  EXPECT_NE(err.find("sig-post: error: disk full\n"), std::string::npos) << err;
  EXPECT_NE(err.find("sig-mesh: error:"), std::string::npos) << err;
}

TEST(Stage, TimeLimitIsAPositiveNumberOfSecondsUpToADay) {
  EXPECT_EQ(parse_time_limit("2.5"), 2.5);
  EXPECT_EQ(parse_time_limit("86400"), 86400);
  for (const char* bad : {"0", "-1", "abc", "2s", "", "86401", "nan"}) {
    try {
      parse_time_limit(bad);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), std::string("--time-limit: '") + bad +
                                           "' is not a number of seconds in (0, 86400]");
    }
  }
}

// The watchdog ends a stage that outlives its budget: status 1, the message, and what the stage
// had not finished (a temporary it registered) removed.
TEST(StageGuard, TimeLimitStopsTheStageAndRemovesItsUnfinishedFiles) {
  ScratchFolder dir;
  const auto temporary = dir / ".case.b.tmp.1";
  EXPECT_EXIT(run_stage("solve",
                        [&] {
                          std::ofstream(temporary) << "half";
                          const Unfinished unfinished(temporary);
                          start_time_limit(0.2, "sig-solve");
                          std::this_thread::sleep_for(std::chrono::seconds(30));
                        }),
              ::testing::ExitedWithCode(1),
              "sig-solve: error: the time limit of 0.2 s \\(--time-limit\\) ran out before "
              "sig-solve finished: stopped, with its unfinished files removed");
  EXPECT_FALSE(std::filesystem::exists(temporary));
  // Within the budget nothing happens, and the watchdog stops with the stage.
  EXPECT_EQ(run_stage("solve", [] { start_time_limit(30, "sig-solve"); }), 0);
}

// A library's exit() inside a stage (libgomp's "Thread creation failed") is an error of the
// stage, whatever status the library gave, with its unfinished files removed.
TEST(StageGuard, LibraryExitInsideAStageIsAnError) {
  ScratchFolder dir;
  const auto temporary = dir / ".case.tae.tmp.1";
  EXPECT_EXIT(run_stage("assemble",
                        [&] {
                          std::ofstream(temporary) << "half";
                          const Unfinished unfinished(temporary);
                          std::exit(0);
                        }),
              ::testing::ExitedWithCode(1),
              "sig-assemble: error: a library ended the stage before it finished");
  EXPECT_FALSE(std::filesystem::exists(temporary));
}

TEST(Stage, DsDateIsTodayAsYyMmDd) {
  const std::string date = ds_date();
  // yy/mm/dd: digits everywhere but at the two slashes (no std::regex: GCC 12 warns inside it).
  ASSERT_EQ(date.size(), 8u) << date;
  for (std::size_t i = 0; i < date.size(); ++i)
    ASSERT_TRUE(i == 2 || i == 5 ? date[i] == '/'
                                 : std::isdigit(static_cast<unsigned char>(date[i])))
        << date;
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  EXPECT_EQ(std::stoi(date.substr(0, 2)), local.tm_year % 100);
  EXPECT_EQ(std::stoi(date.substr(3, 2)), local.tm_mon + 1);
}

TEST(Log, LinesArePrefixedAndProgressIsQuietOffATerminal) {
  ::testing::internal::CaptureStderr(); // a file, not a terminal
  log_info("mesh: 1234 vertices");
  log_warning("nu close to 0.5");
  Progress progress("march", 4);
  for (long step = 1; step <= 4; ++step)
    progress.update(step, "t=0.1");
  progress.finish("energy 1.5");
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("[sig] mesh: 1234 vertices\n"), std::string::npos) << err;
  EXPECT_NE(err.find("[sig] warning: nu close to 0.5\n"), std::string::npos) << err;
  // Updates within 5 s print nothing; the final line is printed once, without \r.
  EXPECT_EQ(err.find("t=0.1"), std::string::npos) << err;
  EXPECT_EQ(err.find('\r'), std::string::npos) << err;
  EXPECT_NE(err.find("[sig] march 4/4 (100%)"), std::string::npos) << err;
  EXPECT_NE(err.find("energy 1.5\n"), std::string::npos) << err;
  EXPECT_NE(err.find(" steps/s"), std::string::npos) << err; // the rate, never "left" when done
  EXPECT_EQ(err.find(" left"), std::string::npos) << err;
}

} // namespace
} // namespace sig
