// sig-adapt: the adaptive loop solve -> estimate -> mark -> refine in one process (issue 29),
// for drivers/adapt.sh, which says what the loop does and measures its errors.
//
//   sig-adapt DATAFILE [-o OUTDIR] [--steps K] [--dofs N] [--theta T] [--clock-start US]
//
// Step k runs the chain of the deck (sig-dump --chain's stages, sig-mesh ... sig-post) into
// OUTDIR/step<k>, then sig-estimate and, but at the last step, sig-refine: each stage's main
// called in this process (stage_main.hpp), so that each still reads and writes its DS files as
// the staged pipeline does (DESIGN.md), with its output in step<k>/chain.log, estimate.log and
// refine.log. Step k > 0 runs OUTDIR/step<k>.dat, the deck with its MESH card replaced by
// `MESH file=step<k-1>/refined.nopo`; the refinements take their arcs from DATAFILE. Why one
// process: a process a stage cost each step some 0.1-0.3 s of start-ups, file checks and an MPI
// singleton (MUMPS), more than the stages' work below some 10^4 dofs, which the uniform mesh
// pays once. OUTDIR/loop.csv gets per step: step, dofs, estimate (sig-estimate's eta),
// estimate_s and refine_s (the stages' own timers: sig-estimate's `seconds`, sig-refine's mark
// and refine), wall_s (the step's chain and estimate), refine_wall_s, and elapsed_s: the wall
// clock from US (microseconds since the epoch, the caller's start of the loop; default: this
// process's start) to the end of the step's estimate, so the process's own start counts.
#include "contact/stage_main.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "material/stage_main.hpp"
#include "mesh/stage_main.hpp"
#include "post/stage_mains.hpp"
#include "stages/stage_mains.hpp"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Runs `stage` (its main) on `argv` with the standard output and error appended to `log`;
/// a failure prints the log and throws.
void run_logged(const std::string& stage, std::vector<std::string> argv, const fs::path& log) {
  using Main = int (*)(int, char**);
  static const std::map<std::string, Main> mains = {
      {"mesh", sig::mesh_main},       {"material", sig::material_main},
      {"contact", sig::contact_main}, {"assemble", sig::assemble_main},
      {"solve", sig::solve_main},     {"march", sig::march_main},
      {"post", sig::post_main},       {"estimate", sig::estimate_main},
      {"refine", sig::refine_main}};
  const auto main = mains.find(stage);
  SIG_VERIFY(main != mains.end(), "sig-adapt: no stage sig-" << stage << " in this process");
  argv.insert(argv.begin(), "sig-" + stage);
  std::vector<char*> args;
  for (std::string& arg : argv)
    args.push_back(arg.data());
  args.push_back(nullptr);
  // The stage's output goes to the log, as a process's would: both streams, then restored.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const int out = dup(1), err = dup(2);
  const int file = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  SIG_VERIFY(out >= 0 && err >= 0 && file >= 0, log.string() << ": cannot open the log");
  dup2(file, 1);
  dup2(file, 2);
  close(file);
  const int code = main->second(static_cast<int>(argv.size()), args.data());
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  dup2(out, 1);
  dup2(err, 2);
  close(out);
  close(err);
  if (code != 0) {
    std::ifstream text(log);
    std::cerr << text.rdbuf();
    SIG_VERIFY(false, "sig-" << stage << " failed (log: " << log.string() << ")");
  }
}

/// The deck of step k > 0: DATAFILE's lines, its MESH card replaced by the refined mesh of step
/// k - 1 (a path relative to the deck's folder, OUTDIR).
fs::path step_deck(const fs::path& datafile, const fs::path& outdir, int k) {
  std::ifstream in(datafile);
  const fs::path deck = outdir / ("step" + std::to_string(k) + ".dat");
  std::ofstream out(deck);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    for (char& c : keyword)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    out << (keyword == "MESH" ? "MESH file=step" + std::to_string(k - 1) + "/refined.nopo" : line)
        << "\n";
  }
  SIG_VERIFY(out.good(), deck.string() << ": cannot write the step's deck");
  return deck;
}

/// `value` in the fewest digits that read back to it.
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return {text, end};
}

/// An option's value: a whole number >= `least`.
long count_option(const std::string& name, const std::string& text, long least) {
  std::size_t used = 0;
  long value = -1;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  SIG_VERIFY(used == text.size() && value >= least,
             name << " " << text << ": expected a whole number >= " << least);
  return value;
}

} // namespace

int main(int argc, char** argv) {
  const Clock::time_point process_start = Clock::now();
  const sig::StageHelp help{
      .name = "sig-adapt",
      .purpose = "The adaptive loop solve -> estimate -> mark -> refine in one process: per step "
                 "the deck's chain of stages, sig-estimate and sig-refine, each stage's main "
                 "called here and writing its DS files to OUTDIR/step<k> (drivers/adapt.sh).",
      .reads = {"DATAFILE (step 0; step k > 0: OUTDIR/step<k>.dat, its MESH card the refined "
                "mesh of step k - 1)"},
      .writes = {"OUTDIR/step<k>/ (every stage's DS files and logs)", "OUTDIR/step<k>.dat",
                 "OUTDIR/loop.csv (per step: dofs, estimate, the stages' and wall times)"},
      .usage = "DATAFILE [-o OUTDIR] [--steps K] [--dofs N] [--theta T] [--clock-start US]",
      .options = {{"--steps K", "at most K steps (default 4)"},
                  {"--dofs N", "stop at the first step with N dofs or more (default 0: none)"},
                  {"--theta T", "Dörfler's fraction, sig-refine's --theta (default 0.5)"},
                  {"--clock-start US",
                   "microseconds since the epoch at which the loop's wall "
                   "clock (elapsed_s) starts (default: this process's start)"}}};
  return sig::run_stage("sig-adapt", [&] {
    // 1. Command line.
    sig::handle_help_and_version(argc, argv, help);
    const std::string usage = "usage: sig-adapt " + help.usage;
    fs::path datafile, outdir;
    long steps = 4, budget = 0;
    std::string theta = "0.5";
    double clock_start_us = -1;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg.empty() || arg[0] != '-') {
        SIG_VERIFY(datafile.empty(), "a second datafile " << arg << "; " << usage);
        datafile = fs::absolute(arg);
        continue;
      }
      SIG_VERIFY(i + 1 < argc, arg << " needs a value; " << usage);
      const std::string value = argv[++i];
      if (arg == "-o")
        outdir = value;
      else if (arg == "--steps")
        steps = count_option(arg, value, 1);
      else if (arg == "--dofs")
        budget = count_option(arg, value, 0);
      else if (arg == "--theta")
        theta = value; // sig-refine checks it
      else if (arg == "--clock-start")
        clock_start_us = count_option(arg, value, 0);
      else
        SIG_VERIFY(false, "unknown option " << arg << "; " << usage);
    }
    SIG_VERIFY(!datafile.empty(), "no datafile; " << usage);
    if (outdir.empty()) outdir = "out/" + datafile.stem().string() + "-adapt";
    const sig::Datafile deck = sig::Datafile::read(datafile);
    const std::vector<std::string> chain = sig::stage_chain(deck);
    fs::create_directories(outdir);
    // The steps' files synced once a step, after its estimate (the refined mesh with the next
    // step's files; the last step is not refined), not one by one (core/ds.hpp).
    sig::defer_file_syncs();
    // The loop's wall clock: from the caller's start when given (the process's own start then
    // counts), else from this main's.
    const auto elapsed = [&] {
      if (clock_start_us < 0) return seconds_since(process_start);
      const auto now = std::chrono::duration_cast<std::chrono::microseconds>(
          std::chrono::system_clock::now().time_since_epoch());
      return (static_cast<double>(now.count()) - clock_start_us) / 1e6;
    };

    // 2. The steps: chain, estimate, then mark and refine but after the last.
    std::ofstream csv(outdir / "loop.csv");
    csv << "step,dofs,estimate,estimate_s,refine_s,wall_s,refine_wall_s,elapsed_s\n";
    for (long k = 0; k < steps; ++k) {
      const fs::path dir = outdir / ("step" + std::to_string(k));
      fs::create_directories(dir);
      const fs::path step = k == 0 ? datafile : step_deck(datafile, outdir, static_cast<int>(k));
      const Clock::time_point start = Clock::now();
      for (const std::string& stage : chain)
        run_logged(stage, {step.string(), "-o", dir.string()}, dir / "chain.log");
      run_logged("estimate", {step.string(), "-o", dir.string()}, dir / "estimate.log");
      sig::sync_deferred_files(dir);
      const double wall = seconds_since(start);
      const double loop_seconds = elapsed();
      const sig::Ds est = sig::read_ds(dir / "case.est", "EST");
      const std::int64_t dofs = est.integer("dofs");
      std::cout << "sig-adapt: step " << k << ": " << dofs << " dofs, estimate "
                << est.scalar("estimate") << std::endl;
      bool last = k == steps - 1;
      if (!last && budget > 0 && dofs >= budget) {
        std::cout << "sig-adapt: " << dofs << " dofs reach the budget of " << budget << ": stopped"
                  << std::endl;
        last = true;
      }
      double refine_s = 0, refine_wall = 0;
      if (!last) {
        const Clock::time_point refine_start = Clock::now();
        run_logged(
            "refine",
            {step.string(), "-o", dir.string(), "--theta", theta, "--shape", datafile.string()},
            dir / "refine.log");
        refine_wall = seconds_since(refine_start);
        std::ifstream log(dir / "refine.log");
        const std::string text{std::istreambuf_iterator<char>(log), {}};
        std::smatch match;
        SIG_VERIFY(std::regex_search(text, match, std::regex("; mark and refine (\\S+) s")),
                   (dir / "refine.log").string() << ": no time of sig-refine");
        refine_s = std::stod(match[1]);
      }
      csv << k << "," << dofs;
      for (const double value : {est.scalar("estimate"), est.scalar("seconds"), refine_s, wall,
                                 refine_wall, loop_seconds})
        csv << "," << shortest(value);
      csv << "\n";
      if (last) break;
    }
    csv.close();
    SIG_VERIFY(csv.good(), (outdir / "loop.csv").string() << ": cannot write");
  });
}
