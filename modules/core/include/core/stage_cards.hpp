#pragma once
// Which cards each stage reads and which file records what it made: the one table that the
// stages' --help (the cards they list), the provenance of their files (core/provenance.hpp: a
// file records the cards its stage read) and the staleness of a case (core/stale.hpp) share.
// tests/pipeline/stage_help.sh checks it against the cards the stages really look up
// (SIG_CARD_TRACE): a card a stage starts to read that the table misses fails the suite, so a
// DS cannot silently depend on a card it does not record.
#include <string>
#include <vector>

namespace sig {

struct StageCards {
  std::string name;               ///< "contact": the program is sig-contact
  std::vector<std::string> cards; ///< keywords it reads, TITLE first, in its --help's order
  /// What it makes for the stages after it: OUTDIR/case.<output>, a DS of kind `kind` that
  /// records the provenance ("" for a stage outside the chain: the benchmarks). sig-mesh's
  /// case.nopo keeps its provenance beside it (case.nopo.prov); sig-post's case.post is the
  /// record of its VTK, JSON and CSV files.
  std::string output;
  std::string kind;
};

/// Every stage: the chain's in chain order (mesh, material, contact, assemble, solve, march,
/// post), then sig-estimate (outside the chain: the adaptive loop's), then the benchmarks
/// (sig-bench-*).
const std::vector<StageCards>& stage_table();

/// The stage called `name` ("contact" or "sig-contact"); throws sig::Error for another name.
const StageCards& stage_cards(const std::string& name);

/// The cards the files a stage writes depend on: its cards, but TITLE for all but sig-post (the
/// title is a name in the DS headers, which no stage reads back; sig-post's files show it).
std::vector<std::string> dependency_cards(const StageCards& stage);

/// The stage of the chain that writes DS kind `kind` (MILI: material), nullptr if none.
const StageCards* stage_writing(const std::string& kind);

} // namespace sig
