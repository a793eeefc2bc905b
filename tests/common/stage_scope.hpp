#pragma once
// A hand-made case for a stage's test: the files written while a StageScope lives are written as
// the stage `stage` would write them for the datafile `deck`: they record the deck's cards
// (core/provenance.hpp), so that the stage under test, run on the same deck, takes them as up to
// date.
#include "core/datafile.hpp"
#include "core/provenance.hpp"

#include <filesystem>
#include <string>

namespace sig::testing {

class StageScope {
public:
  StageScope(const std::filesystem::path& outdir, const std::filesystem::path& deck,
             const std::string& stage) {
    open_case(outdir, Datafile::read(deck), stage);
  }
  ~StageScope() { close_case(); }
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;
};

} // namespace sig::testing
