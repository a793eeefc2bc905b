#pragma once
// Which stages of a case must run again for a deck, the way make would say it, from what the
// files of the case record (core/provenance.hpp) rather than from their dates: a stage of the
// deck's chain is stale when
//  - its output (core/stage_cards.hpp: case.nopo with case.nopo.prov, case.mili, ...,
//    case.post) is missing, unreadable, or records no deck;
//  - its output records a card with other values than the deck now gives, or misses a card the
//    stage reads;
//  - an input its output records is stale itself, or is no longer the file it was made from
//    (another fingerprint: rerun alone, replaced, copied in);
//  - (sig-post) a file case.post lists is gone.
// drivers/chain.sh asks `sig-dump --stale DATAFILE OUTDIR` and runs those stages only.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sig {

class Datafile;

struct StaleStage {
  std::string stage; ///< "contact"
  std::string why;   ///< "OUTDIR/case.cont was made with FRICTION mu=0.4, but ..."
};

/// The fingerprint of a file that is not a DS (case.nopo) as its reader computes it; throws
/// sig::Error when it cannot read the file.
using FileFingerprint = std::function<std::uint64_t(const std::filesystem::path&)>;

/// The stale stages of `deck`'s chain (core/stage.hpp stage_chain) for the case in `outdir`, in
/// chain order. Reads the files, registers no input (call it outside a stage).
std::vector<StaleStage> stale_stages(const Datafile& deck, const std::filesystem::path& outdir,
                                     const FileFingerprint& nopo_fingerprint);

} // namespace sig
