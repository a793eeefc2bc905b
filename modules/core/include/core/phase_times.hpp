#pragma once
// Where a stage's wall time goes, for drivers/bench-pipeline.sh: the seconds spent in each kind
// of work, summed over the process. The file readers and writers time themselves ("read": a DS or
// mesh file read and checked, CRCs, fingerprints and provenance included; "write": encoded,
// written, synced and renamed into place); a stage main times its own computation under its
// name ("gmsh", "assemble", "solve", "post"). A phase nested in a phase of the same name counts
// once. With SIG_PHASE_TIMES=FILE in the environment, run_stage (core/stage.hpp) appends one line
// per phase to FILE when the stage ends: "PROGRAM<TAB>PHASE<TAB>SECONDS", the phase "total" being
// the time from the process's start to that moment.
#include <string>
#include <utility>
#include <vector>

namespace sig {

/// Adds the seconds of its lifetime to `phase` (a string literal) unless a timer of the same
/// phase is already running.
class PhaseTimer {
public:
  explicit PhaseTimer(const char* phase);
  ~PhaseTimer();
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

private:
  const char* phase_;
  bool outermost_;
  double start_;
};

/// The phases timed so far, in the order they first ran, with their seconds.
std::vector<std::pair<std::string, double>> phase_times();
/// Forgets them, none running: run_stage does at a stage's end, so that the next stage in the
/// same process (the adaptive loop, sig-adapt) records its own.
void forget_phase_times();

/// Seconds since the process started (its first timer or static initialisation of core).
double process_seconds();

/// When $SIG_PHASE_TIMES names a file: append the phases and "total" of `program` to it.
void append_phase_times(const std::string& program);

} // namespace sig
