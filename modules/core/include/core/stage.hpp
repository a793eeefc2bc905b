#pragma once
// What every stage main shares: the command line `sig-<stage> DATAFILE [-o OUTDIR]`, the output
// folder (default out/<datafile stem>/), the DS paths in it, and the catch-all that turns any
// exception into a message and a non-zero exit.
#include <filesystem>
#include <functional>
#include <string>

namespace sig {

struct StageArgs {
  std::filesystem::path datafile;
  std::filesystem::path outdir;
  /// Path of a DS of this case in outdir: ds_path("nopo") -> OUTDIR/case.nopo
  std::filesystem::path ds_path(const std::string& extension) const;
};

/// Parse `DATAFILE [-o OUTDIR]`; creates OUTDIR, removes the temporaries killed stages left in
/// it (remove_stale_temporaries) and opens the case: the DS files in OUTDIR it reads are checked
/// to belong together (core/provenance.hpp). Throws sig::Error with a usage line.
StageArgs parse_stage_args(int argc, char** argv, const std::string& stage);

/// Run `body`, printing "stage: error: ..." and returning 1 on any exception, 0 otherwise; a
/// failed write to the standard output (a full disk, /dev/full) is an error too.
int run_stage(const std::string& stage, const std::function<void()>& body);

/// Today's date as MODULEF writes it in DS headers: "yy/mm/dd".
std::string ds_date();

} // namespace sig
