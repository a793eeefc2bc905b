#pragma once
// What the benchmark executables (sig-bench-*) share: their command line and the median they
// report, so that every benchmark reads --repeat and summarises its runs the same way.
#include "core/stage.hpp"

#include <vector>

namespace sig {

/// `DATAFILE [-o OUTDIR] [--repeat K]`: the stage's arguments and K >= 1 timed runs.
struct BenchArgs : StageArgs {
  int repeat = 3;
};

/// Parse a benchmark's command line (--help and --version as every stage): --repeat K, default
/// 3, the rest as parse_stage_args. Throws sig::Error for a missing or non-positive K.
BenchArgs parse_bench_args(int argc, char** argv, const StageHelp& help);

/// The middle value of `values`, the mean of the middle two for an even count.
double median(std::vector<double> values);

} // namespace sig
