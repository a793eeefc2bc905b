#include "core/stage.hpp"

#include "core/card_help.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/phase_times.hpp"
#include "core/provenance.hpp"
#include "core/stage_guard.hpp"
#include "revision.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>

namespace sig {

namespace {
// Stages are named "mesh" or "sig-mesh" by their mains; messages always say "sig-mesh".
std::string program_name(const std::string& stage) {
  return stage.rfind("sig-", 0) == 0 ? stage : "sig-" + stage;
}

std::string list_lines(const std::vector<std::string>& items, std::size_t indent) {
  std::string out;
  for (const std::string& item : items)
    out += "  " + wrap_text(item, 2, indent);
  return out;
}

std::function<std::string(const std::string&)>& factorization_explainer() {
  static std::function<std::string(const std::string&)> explain;
  return explain;
}

// The stage's words for a failed factorization; the solver's message if it has none, or if
// finding the words fails in turn.
std::string explained(const FactorizationFailure& failure) {
  if (!factorization_explainer()) return failure.what();
  try {
    return factorization_explainer()(failure.what());
  } catch (const std::exception& e) {
    return std::string(failure.what()) + " (and its cause could not be named: " + e.what() + ")";
  }
}

// The cards the stage looked up, for the test suite's check of --help (stage_help.sh).
void append_card_trace(const std::string& program) {
  const char* file = std::getenv("SIG_CARD_TRACE");
  if (file == nullptr || *file == '\0' || cards_looked_up().empty()) return;
  std::string lines;
  for (const std::string& keyword : cards_looked_up())
    lines += program + " " + keyword + "\n";
  std::ofstream(file, std::ios::app) << lines;
}
} // namespace

std::string stage_help_text(const StageHelp& help) {
  const std::string name = program_name(help.name);
  std::string out = "usage: " + name + " " + help.usage + "\n       " + name +
                    " --help | --version\n\n" + wrap_text(help.purpose, 0, 0) + "\n";
  if (!help.reads.empty()) out += "Reads:\n" + list_lines(help.reads, 4);
  if (!help.writes.empty()) out += "Writes:\n" + list_lines(help.writes, 4);
  std::vector<std::pair<std::string, std::string>> options;
  if (help.usage.find("-o OUTDIR") != std::string::npos)
    options.emplace_back("-o OUTDIR", "the case's folder, where the stages read and write their "
                                      "files (default out/<datafile stem>/)");
  if (help.usage.find("--time-limit") != std::string::npos)
    options.emplace_back("--time-limit SECONDS",
                         "the wall-clock budget: when it runs out the stage stops with an "
                         "error, its unfinished files removed (default none)");
  options.insert(options.end(), help.options.begin(), help.options.end());
  options.emplace_back("-h, --help", "this help");
  options.emplace_back("--version", "version and git revision");
  std::size_t width = 0;
  for (const auto& option : options)
    width = std::max(width, option.first.size());
  out += "\nOptions:\n";
  for (auto [option, text] : options) {
    option.resize(width, ' ');
    out += "  " + option + "  " + wrap_text(text, width + 4, width + 4);
  }
  if (!help.cards.empty()) {
    out += '\n';
    out += wrap_text("Cards it reads (one per line, KEYWORD name=value ...; keywords and "
                     "names are case-insensitive, # starts a comment; all the cards: "
                     "sig-dump --cards):",
                     0, 0);
    for (const std::string& keyword : help.cards) {
      const CardSpec* spec = find_card_spec(keyword);
      SIG_VERIFY(spec != nullptr, name << ": --help lists card " << keyword
                                       << ", which the card schema does not have");
      out += card_help(*spec);
    }
  }
  return out;
}

std::string version_line(const std::string& name) {
  return program_name(name) + " (Signorini) " + build_version() + ", revision " + build_revision();
}

void handle_help_and_version(int argc, char** argv, const StageHelp& help) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << stage_help_text(help);
      throw StageExit{0};
    }
    if (arg == "--version") {
      std::cout << version_line(help.name) << "\n";
      throw StageExit{0};
    }
  }
}

std::filesystem::path StageArgs::ds_path(const std::string& extension) const {
  return outdir / ("case." + extension);
}

double parse_time_limit(const std::string& text) {
  double seconds = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  SIG_VERIFY(error == std::errc{} && end == text.data() + text.size() && seconds > 0 &&
                 seconds <= kMaxTimeLimit,
             "--time-limit: '" << text << "' is not a number of seconds in (0, " << kMaxTimeLimit
                               << "]");
  return seconds;
}

StageArgs parse_stage_args(int argc, char** argv, const StageHelp& help) {
  handle_help_and_version(argc, argv, help);
  const std::string usage = "usage: " + program_name(help.name) + " " + help.usage +
                            " (--help: what it reads, writes and the cards it uses)";
  StageArgs args;
  bool have_outdir = false;
  double time_limit = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o") {
      SIG_VERIFY(i + 1 < argc && !have_outdir, usage);
      args.outdir = argv[++i];
      have_outdir = true;
    } else if (arg == "--time-limit") {
      SIG_VERIFY(i + 1 < argc && time_limit == 0, usage);
      time_limit = parse_time_limit(argv[++i]);
    } else {
      SIG_VERIFY(!arg.empty() && arg[0] != '-' && args.datafile.empty(), usage);
      args.datafile = arg;
    }
  }
  SIG_VERIFY(!args.datafile.empty(), usage);
  if (time_limit > 0) start_time_limit(time_limit, program_name(help.name));
  if (!have_outdir) args.outdir = std::filesystem::path("out") / args.datafile.stem();
  SIG_VERIFY(!args.outdir.empty(), usage);
  std::error_code error;
  std::filesystem::create_directories(args.outdir, error);
  SIG_VERIFY(!error, args.outdir.string() << ": cannot create output folder: " << error.message());
  // What a killed stage left: its temporaries would otherwise pile up in OUTDIR forever.
  for (const std::string& name : remove_stale_temporaries(args.outdir))
    log_info("removed " + (args.outdir / name).string() + ", left by a stage that was killed");
  args.deck = Datafile::read(args.datafile);
  open_case(args.outdir, args.deck, help.name);
  return args;
}

int run_stage(const std::string& stage, const std::function<void()>& body) {
  int code = 1;
  close_case();
  enter_stage_body(program_name(stage));
  try {
    body();
    code = 0;
  } catch (const StageExit& exit) {
    code = exit.code;
  } catch (const FactorizationFailure& failure) {
    std::cerr << program_name(stage) << ": error: " << explained(failure) << std::endl;
  } catch (const std::exception& e) {
    std::cerr << program_name(stage) << ": error: " << e.what() << std::endl;
  } catch (...) {
    std::cerr << program_name(stage) << ": error: unknown exception" << std::endl;
  }
  leave_stage_body();
  append_phase_times(program_name(stage));
  factorization_explainer() = nullptr;
  close_case();
  // What the stage printed is a result too (sig-dump > file): a failed write is an error.
  std::cout.flush();
  errno = 0;
  if (code == 0 && !(std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout))) {
    std::cerr << program_name(stage) << ": error: cannot write to the standard output"
              << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string())
              << std::endl;
    code = 1;
  }
  append_card_trace(program_name(stage));
  forget_cards_looked_up();
  forget_phase_times();
  return code;
}

void explain_factorization_failures(std::function<std::string(const std::string&)> explain) {
  factorization_explainer() = std::move(explain);
}

std::vector<std::string> stage_chain(const Datafile& datafile) {
  // The cards are looked at, not read (Datafile::find would count them as read by sig-dump).
  const auto has = [&](const char* keyword) {
    return std::any_of(datafile.cards().begin(), datafile.cards().end(),
                       [&](const Card& card) { return card.keyword == keyword; });
  };
  std::vector<std::string> stages{"mesh", "material"};
  if (has("CONTACT")) stages.emplace_back("contact");
  stages.emplace_back("assemble");
  stages.emplace_back(has("TIME") ? "march" : "solve");
  stages.emplace_back("post");
  return stages;
}

std::string ds_date() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%y/%m/%d", &local);
  return text;
}

} // namespace sig
