#include "core/stale.hpp"

#include "core/card_fingerprint.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/provenance.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace sig {

namespace {

// The files of one case as they are now, read once each.
class CaseFiles {
public:
  CaseFiles(std::filesystem::path outdir, FileFingerprint nopo)
      : outdir_(std::move(outdir)), nopo_(std::move(nopo)) {}

  std::filesystem::path path_of(const std::string& kind) const {
    const StageCards* stage = stage_writing(kind);
    return outdir_ / ("case." + (stage != nullptr ? stage->output : kind));
  }

  /// The fingerprint of the file of `kind`, or the reason there is none.
  const std::pair<std::optional<std::uint64_t>, std::string>& fingerprint(const std::string& kind) {
    const auto known = fingerprints_.find(kind);
    if (known != fingerprints_.end()) return known->second;
    auto& found = fingerprints_[kind];
    const std::filesystem::path path = path_of(kind);
    try {
      if (!std::filesystem::exists(path)) throw Error(path.string() + " does not exist");
      // The fingerprint folds the stored CRCs: no payload needs reading (the stage that reads
      // the file checks them).
      found.first =
          kind == "NOPO"
              ? nopo_(path)
              : read_ds_record(path, kind, [](const std::string&) { return false; }).fingerprint;
    } catch (const std::exception& e) {
      found.second = e.what();
    }
    return found;
  }

private:
  std::filesystem::path outdir_;
  FileFingerprint nopo_;
  std::map<std::string, std::pair<std::optional<std::uint64_t>, std::string>> fingerprints_;
};

// Why the output of `stage` is not up to date for `deck`, or "" when it is.
std::string why_stale(const StageCards& stage, const Datafile& deck, CaseFiles& files,
                      const std::set<std::string>& stale_kinds) {
  const std::filesystem::path output = files.path_of(stage.kind);
  const bool beside = stage.kind == "NOPO"; // its provenance is in case.nopo.prov
  const std::filesystem::path record_path = beside ? provenance_beside(output) : output;
  if (!std::filesystem::exists(output)) return output.string() + " does not exist";
  if (!std::filesystem::exists(record_path)) return record_path.string() + " does not exist";
  Provenance provenance;
  try {
    const Ds record = read_ds_record(record_path, stage.kind, [](const std::string& name) {
      return name == "fingerprint" || name == "files";
    });
    if (beside) {
      const auto& [fingerprint, error] = files.fingerprint(stage.kind);
      if (!fingerprint) return error;
      if (!record.has("fingerprint") ||
          record.text("fingerprint") != fingerprint_text(*fingerprint))
        return output.string() + " is not the file " + record_path.string() + " records";
    }
    if (record.has("provenance"))
      provenance = parse_provenance(record.text("provenance"), record_path.string());
    if (record.has("files")) {
      std::istringstream names(record.text("files"));
      for (std::string name; std::getline(names, name);)
        if (!name.empty() && !std::filesystem::exists(output.parent_path() / name))
          return (output.parent_path() / name).string() + ", which " + output.string() +
                 " lists, does not exist";
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  if (provenance.cards.empty())
    return output.string() + " records no deck it was made from (an older Signorini)";
  for (const std::string& keyword : dependency_cards(stage))
    if (std::none_of(provenance.cards.begin(), provenance.cards.end(),
                     [&](const CardRecord& card) { return card.keyword == keyword; }))
      return output.string() + " does not record the card " + keyword + " sig-" + stage.name +
             " reads (an older Signorini)";
  for (const CardRecord& card : provenance.cards)
    if (const std::string change = card_change(card, deck); !change.empty())
      return output.string() + " was made " + change;
  for (const ProvenanceEntry& input : provenance.inputs) {
    const std::string path = files.path_of(input.kind).string();
    if (stale_kinds.count(input.kind) != 0) return "it was made from " + path + ", which is stale";
    const auto& [fingerprint, error] = files.fingerprint(input.kind);
    if (!fingerprint) return "it was made from " + path + ": " + error;
    if (*fingerprint != input.fingerprint)
      return path + " changed since " + output.string() + " was made from it";
  }
  return "";
}

} // namespace

std::vector<StaleStage> stale_stages(const Datafile& deck, const std::filesystem::path& outdir,
                                     const FileFingerprint& nopo_fingerprint) {
  CaseFiles files(outdir, nopo_fingerprint);
  std::set<std::string> stale_kinds;
  std::vector<StaleStage> stale;
  for (const std::string& name : stage_chain(deck)) {
    const StageCards& stage = stage_cards(name);
    const std::string why = why_stale(stage, deck, files, stale_kinds);
    if (why.empty()) continue;
    stale.push_back({name, why});
    stale_kinds.insert(stage.kind);
  }
  return stale;
}

} // namespace sig
