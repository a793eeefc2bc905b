#pragma once
// The files of a case belong together. Inside a stage (parse_stage_args opens the case, run_stage
// closes it) every input of the case in OUTDIR has a fingerprint: the mesh (case.nopo, registered
// by the NOPO reader) and every DS read_ds reads. A DS records what it was built from:
// write_ds adds the Text array "provenance", one line per input kind,
//     KIND FINGERPRINT FILE        e.g.  NOPO 6c2f0e4b1d9a8e37 out/hertz/case.nopo
// with the inputs of the inputs too (TAE records NOPO and MILI, B records TAE, CONT, MILI and
// NOPO). read_ds then checks each DS of the case against the others: two statements about one
// kind (a file read, or a line of a provenance) that disagree are an error naming both files,
// e.g. sig-post given another case's case.mili, or sig-assemble a foreign case.nopo.
//
// Nothing to do in a stage main or a new DS: read_ds / write_ds / read_nopo do it. A stage that
// reads files of another case (a reference solution) reads them from outside OUTDIR: only files
// in OUTDIR are inputs of the case.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sig {

/// One input a file was built from.
struct ProvenanceEntry {
  std::string kind; ///< NOPO, MILI, CONT, TAE, B, HIST ...
  std::uint64_t fingerprint = 0;
  std::string file; ///< as the stage that read it named it
};

/// Open the case of a stage: files in `outdir` are its inputs from now on.
void open_case(const std::filesystem::path& outdir);
/// Forget the case (run_stage does it when the stage ends).
void close_case();
/// The folder of the open case, or an empty path outside a stage.
std::filesystem::path case_folder();

/// Register an input of the case read from `file`, with what it records to be built from.
/// Does nothing outside a case or for a file outside OUTDIR. Throws sig::Error naming both files
/// when a statement about one kind disagrees with an earlier one.
void note_case_input(const std::string& kind, const std::filesystem::path& file,
                     std::uint64_t fingerprint, const std::vector<ProvenanceEntry>& built_from);

/// The provenance to record in a DS of kind `kind` written now: every input of the case but
/// those of that kind (a stage may read the previous file it replaces). Empty outside a case.
std::vector<ProvenanceEntry> case_provenance(const std::string& kind);

/// The "provenance" text array of a DS and back (errors name `file`).
std::string provenance_text(const std::vector<ProvenanceEntry>& entries);
std::vector<ProvenanceEntry> parse_provenance(const std::string& text, const std::string& file);

} // namespace sig
