#pragma once
// The files of a case belong together, and to the deck. Inside a stage (parse_stage_args opens
// the case with the stage's deck, run_stage closes it) every input of the case in OUTDIR has a
// fingerprint: the mesh (case.nopo, registered by the NOPO reader) and every DS read_ds reads. A
// DS records what it was built from: write_ds adds the Text array "provenance",
//     KIND FINGERPRINT FILE          one line per input file,  e.g.
//     NOPO 6c2f0e4b1d9a8e37 out/hertz/case.nopo
//     CARD KEYWORD FINGERPRINT VALUES  one line per card keyword it depends on, e.g.
//     CARD FRICTION abbb4f06e393644d ref=3 law=coulomb mu=0.4 bound=normal of=slip
// The inputs of the inputs are recorded too, and so are their cards: the provenance of a file is
// its own stage's cards (core/stage_cards.hpp) plus everything its inputs record (B records TAE,
// CONT, MILI and NOPO, and the cards of sig-solve, sig-assemble, sig-contact, sig-material and
// sig-mesh). The values are the deck's parsed values, not its text (core/card_fingerprint.hpp).
//
// read_ds then checks each input of the stage
//  - against the other inputs: two statements about one kind (a file read, or a line of a
//    provenance) that disagree are an error naming both files (sig-post given another case's
//    case.mili, sig-assemble a foreign case.nopo);
//  - against the deck: a card the input records with other values than the deck now gives is an
//    error naming the file, the card and the fields that changed, the deck's line, and the stage
//    to rerun (the first of the deck's chain that reads the card): a file made before the deck
//    was edited, or made from another deck and copied in. A file that records no card at all
//    (written by an older Signorini) is refused the same way.
//
// A file that is not a DS keeps its provenance beside it in FILE.prov (a DS of the file's kind
// holding the provenance and the fingerprint of the file it describes): case.nopo, which
// MODULEF's and FreeFem's readers must still read as they always have.
//
// Derived files to come carry their provenance the same way, with nothing new here:
//  - a mesh made by refinement is written by write_nopo, so its FILE.prov records the refining
//    stage's cards (an ADAPT card) plus everything its inputs record: the coarse mesh's MESH
//    card, the indicators' DS and, through it, the solution's cards. A change of any card up the
//    adaptive loop makes the refined mesh and what was built on it stale. The coarse mesh is an
//    input of a kind of its own (a level's, e.g. "NP1"), since one kind is one file in a case.
//  - the per-rank parts of a distributed assembly (case.tae.r3, assembly/tae_parts.hpp) are
//    written by write_ds like any DS and record the deck's cards and their inputs, but a reader
//    does not register them (read_ds_record_streamed): it registers their index, case.tae, and
//    checks each part's stamp (rank, number of ranks, run) against the index, so that a case
//    keeps one file per kind and parts of two runs or partitions are refused.
//
// Nothing to do in a stage main or a new DS: read_ds / write_ds / read_nopo / write_nopo do it.
// A stage that reads files of another case (a reference solution) reads them from outside
// OUTDIR: only files in OUTDIR are inputs of the case.
#include "core/card_fingerprint.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sig {

class Datafile;

/// One input a file was built from.
struct ProvenanceEntry {
  std::string kind; ///< NOPO, MILI, CONT, TAE, B, HIST ...
  std::uint64_t fingerprint = 0;
  std::string file; ///< as the stage that read it named it
};

/// What a file records of its making: the files and the cards of the deck.
struct Provenance {
  std::vector<ProvenanceEntry> inputs;
  std::vector<CardRecord> cards;
  bool empty() const { return inputs.empty() && cards.empty(); }
};

/// Open the case of a stage: files in `outdir` are its inputs from now on.
void open_case(const std::filesystem::path& outdir);
/// The same for the stage `stage` ("solve") given `deck`: the inputs' card records are checked
/// against the deck, and the files the stage writes record the cards it reads.
void open_case(const std::filesystem::path& outdir, const Datafile& deck, const std::string& stage);
/// Forget the case (run_stage does it when the stage ends).
void close_case();
/// The folder of the open case, or an empty path outside a stage.
std::filesystem::path case_folder();

/// Register an input of the case read from `file`, with what it records to be built from.
/// Does nothing outside a case or for a file outside OUTDIR. Throws sig::Error naming both files
/// when a statement about one kind disagrees with an earlier one, and naming the file, the card
/// and the stage to rerun when a card it records is not the deck's.
void note_case_input(const std::string& kind, const std::filesystem::path& file,
                     std::uint64_t fingerprint, const Provenance& built_from);

/// Register a file that is not a DS (case.nopo) with the provenance beside it (FILE.prov, or
/// beside the file a link points to). Inside a case with a deck the record must be there and
/// describe this very file: else sig::Error naming the file and the stage to rerun.
void note_case_file(const std::string& kind, const std::filesystem::path& file,
                    std::uint64_t fingerprint);

/// Inside a case: write FILE.prov, the provenance of `file` (of kind `kind`, whose fingerprint
/// is `fingerprint`) as a DS of that kind; outside a case, nothing.
void write_provenance_beside(const std::filesystem::path& file, const std::string& kind,
                             std::uint64_t fingerprint, const std::string& title,
                             const std::string& creator);

/// FILE.prov.
std::filesystem::path provenance_beside(const std::filesystem::path& file);

/// The provenance to record in a DS of kind `kind` written now: every input of the case but
/// those of that kind (a stage may read the previous file it replaces), the cards they record,
/// and the stage's own cards. Empty outside a case.
Provenance case_provenance(const std::string& kind);

/// The "provenance" text array of a DS and back (errors name `file`).
std::string provenance_text(const Provenance& provenance);
Provenance parse_provenance(const std::string& text, const std::string& file);

/// The stage of `deck`'s chain to rerun when its card `keyword` changed: the first that reads
/// it ("sig-contact" for FRICTION), else `fallback`.
std::string stage_to_rerun(const Datafile& deck, const std::string& keyword,
                           const std::string& fallback);

} // namespace sig
