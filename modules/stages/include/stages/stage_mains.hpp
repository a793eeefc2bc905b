#pragma once
// The stage's main as a function: its executable calls it, and so does the adaptive loop
// (sig-adapt), which runs a step's stages in its own process, each writing its DS files.
namespace sig {

/// sig-assemble, sig-solve and sig-march with this command line (argv[0] the program's name):
/// the exit status. sig-assemble is a stage of this layer for its distributed form (a rank's
/// part of the partition, stages/rank_rows.hpp).
int assemble_main(int argc, char** argv);
int solve_main(int argc, char** argv);
int march_main(int argc, char** argv);

} // namespace sig
