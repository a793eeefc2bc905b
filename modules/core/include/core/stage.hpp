#pragma once
// What every stage main shares: the command line `sig-<stage> DATAFILE [-o OUTDIR]` with --help
// and --version, the output folder (default out/<datafile stem>/), the DS paths in it, and the
// catch-all that turns any exception into a message and a non-zero exit.
#include "core/datafile.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sig {

/// What a stage's --help says. The cards are keywords of the card schema (cards.cpp), printed
/// with their fields, help texts and defaults from there: list every card the stage reads
/// (tests/pipeline/stage_help.sh checks it against the cards the stages look up).
struct StageHelp {
  std::string name{};                ///< "sig-solve"
  std::string purpose{};             ///< one sentence: what the stage does
  std::vector<std::string> reads{};  ///< files, e.g. "OUTDIR/case.tae (sig-assemble)"
  std::vector<std::string> writes{}; ///< files, e.g. "OUTDIR/case.b"
  std::vector<std::string> cards{};  ///< keywords, in the order shown
  std::string usage = "DATAFILE [-o OUTDIR] [--time-limit SECONDS]";
  /// Options beside -o, --help and --version: {"--repeat K", "timed runs (default 3)"}.
  std::vector<std::pair<std::string, std::string>> options{};
};

/// The --help text: usage, purpose, files, options and every card with its fields.
std::string stage_help_text(const StageHelp& help);

/// "NAME (Signorini) VERSION, revision REV" (the git revision the build was made from).
std::string version_line(const std::string& name);

/// Thrown by the argument parsers after printing --help or --version; run_stage returns `code`.
struct StageExit {
  int code = 0;
};

/// --help / -h or --version anywhere on the command line: print and throw StageExit{0}.
void handle_help_and_version(int argc, char** argv, const StageHelp& help);

struct StageArgs {
  std::filesystem::path datafile;
  std::filesystem::path outdir;
  Datafile deck; ///< the datafile, read (parse_stage_args)
  /// Path of a DS of this case in outdir: ds_path("nopo") -> OUTDIR/case.nopo
  std::filesystem::path ds_path(const std::string& extension) const;
};

/// The seconds of `--time-limit SECONDS`: a number in (0, kMaxTimeLimit] (core/stage_guard.hpp).
double parse_time_limit(const std::string& text);

/// Parse `DATAFILE [-o OUTDIR] [--time-limit SECONDS]` (after handle_help_and_version) and start
/// the time limit (core/stage_guard.hpp); creates OUTDIR, removes the
/// temporaries killed stages left in it (remove_stale_temporaries), reads the datafile and opens
/// the case: the DS files in OUTDIR the stage reads are checked to belong together and to the
/// deck, and the ones it writes record the cards it reads (help.name in core/stage_cards.hpp;
/// core/provenance.hpp). Throws sig::Error with the usage line, or the datafile's errors.
StageArgs parse_stage_args(int argc, char** argv, const StageHelp& help);

/// Run `body`, printing "stage: error: ..." and returning 1 on any exception, 0 otherwise
/// (StageExit: its code); a failed write to the standard output (a full disk, /dev/full) is an
/// error too, and so is a library's exit() inside `body` (core/stage_guard.hpp). With
/// SIG_CARD_TRACE=FILE in the environment (the test suite) it appends "STAGE KEYWORD" to FILE for
/// every card the stage looked up.
int run_stage(const std::string& stage, const std::function<void()>& body);

/// The stages a datafile's chain runs, in order, as the stages' own parser reads the deck
/// (drivers/chain.sh asks `sig-dump --chain`, so that a deck with CR line ends or a lower-case
/// keyword gets the chain its cards call for): mesh, material, contact (with a CONTACT card),
/// assemble, then march (with a TIME card) or solve, and post.
std::vector<std::string> stage_chain(const Datafile& datafile);

/// A stage that knows what its matrices mean gives run_stage the words for their failure to
/// factorize: a FactorizationFailure (core/error.hpp) out of its body is then printed as
/// `explain(the linear solver's message)` instead of the bare message (until run_stage ends).
/// It is called after the body's stack is gone: it must own what it uses (captures by value).
void explain_factorization_failures(std::function<std::string(const std::string&)> explain);

/// Today's date as MODULEF writes it in DS headers: "yy/mm/dd".
std::string ds_date();

} // namespace sig
