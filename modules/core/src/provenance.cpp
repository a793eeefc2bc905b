#include "core/provenance.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

namespace sig {

namespace {

constexpr const char* card_tag = "CARD";
constexpr const char* rerun_hint = " (drivers/chain.sh reruns only what is stale)";

/// What the stage has learnt about one kind of input: the file itself (stated_by == file) or a
/// line of the provenance of `stated_by`.
struct Statement {
  ProvenanceEntry entry;
  std::string stated_by;
  bool direct() const { return stated_by == entry.file; }
};

struct Case {
  std::filesystem::path folder;
  std::vector<Statement> statements;
  std::vector<CardRecord> cards; ///< recorded by the inputs, one per keyword
  std::optional<Datafile> deck;
  std::string stage;                            ///< "solve"
  std::map<std::string, std::uint64_t> deck_fp; ///< the deck's card fingerprints, by keyword
};

std::optional<Case>& current_case() {
  static std::optional<Case> state;
  return state;
}

std::filesystem::path folder_of(const std::filesystem::path& file) {
  std::error_code ignored;
  const auto parent = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  return std::filesystem::weakly_canonical(parent, ignored);
}

std::string describe(const Statement& s) {
  const std::string fp = fingerprint_text(s.entry.fingerprint);
  if (s.direct()) return s.entry.file + " is the " + s.entry.kind + " with fingerprint " + fp;
  return s.stated_by + " was built from the " + s.entry.kind + " " + s.entry.file +
         " with fingerprint " + fp;
}

std::string writer_of(const std::string& kind) {
  const StageCards* stage = stage_writing(kind);
  return stage != nullptr ? "sig-" + stage->name : "the stage that wrote it";
}

std::uint64_t deck_fingerprint(Case& state, const std::string& keyword) {
  const auto known = state.deck_fp.find(keyword);
  if (known != state.deck_fp.end()) return known->second;
  return state.deck_fp[keyword] = card_record(*state.deck, keyword).fingerprint;
}

// A file of the case must record the deck, and the deck it records must be this one.
void check_against_deck(Case& state, const std::string& kind, const std::string& file,
                        const std::vector<CardRecord>& cards) {
  const Datafile& deck = *state.deck;
  SIG_VERIFY(!cards.empty(), file << " records no deck it was made from (written by an older "
                                     "Signorini, or outside a stage): rerun "
                                  << writer_of(kind) << " and the stages after it" << rerun_hint);
  for (const CardRecord& card : cards) {
    if (deck_fingerprint(state, card.keyword) == card.fingerprint) continue;
    const std::string stage = stage_to_rerun(deck, card.keyword, writer_of(kind));
    throw Error(file + " was made " + card_change(card, deck) + ": " + file +
                " is stale (made before the deck changed, or from another deck); rerun " + stage +
                " and the stages after it" + rerun_hint);
  }
}

} // namespace

void open_case(const std::filesystem::path& outdir) {
  current_case() = Case{folder_of(outdir / "x"), {}, {}, {}, {}, {}};
}

void open_case(const std::filesystem::path& outdir, const Datafile& deck,
               const std::string& stage) {
  open_case(outdir);
  current_case()->deck = deck;
  current_case()->stage = stage_cards(stage).name;
}

void close_case() {
  current_case().reset();
}

std::filesystem::path case_folder() {
  return current_case() ? current_case()->folder : std::filesystem::path();
}

std::string stage_to_rerun(const Datafile& deck, const std::string& keyword,
                           const std::string& fallback) {
  for (const std::string& name : stage_chain(deck)) {
    const auto& cards = stage_cards(name).cards;
    if (std::find(cards.begin(), cards.end(), keyword) != cards.end()) return "sig-" + name;
  }
  return fallback;
}

void note_case_input(const std::string& kind, const std::filesystem::path& file,
                     std::uint64_t fingerprint, const Provenance& built_from) {
  std::optional<Case>& state = current_case();
  if (!state || folder_of(file) != state->folder) return;
  std::vector<Statement> fresh{{{kind, fingerprint, file.string()}, file.string()}};
  for (const ProvenanceEntry& entry : built_from.inputs)
    fresh.push_back({entry, file.string()});
  for (const Statement& s : fresh) {
    for (const Statement& earlier : state->statements) {
      if (earlier.entry.kind != s.entry.kind || earlier.entry.fingerprint == s.entry.fingerprint)
        continue;
      throw Error("the files of this case do not belong together: " + describe(earlier) + ", but " +
                  describe(s) +
                  ". Rerun the chain from the stage that writes the older file (each case in its "
                  "own output folder)");
    }
  }
  if (state->deck) check_against_deck(*state, kind, file.string(), built_from.cards);
  state->statements.insert(state->statements.end(), fresh.begin(), fresh.end());
  for (const CardRecord& card : built_from.cards)
    if (std::none_of(state->cards.begin(), state->cards.end(),
                     [&](const CardRecord& known) { return known.keyword == card.keyword; }))
      state->cards.push_back(card);
}

std::filesystem::path provenance_beside(const std::filesystem::path& file) {
  return file.string() + ".prov";
}

void note_case_file(const std::string& kind, const std::filesystem::path& file,
                    std::uint64_t fingerprint) {
  const std::optional<Case>& state = current_case();
  if (!state || folder_of(file) != state->folder) return;
  // A linked file (a run reusing the mesh of another) has its record beside the file it links to.
  std::filesystem::path record = provenance_beside(file);
  std::error_code error;
  if (!std::filesystem::exists(record, error) && std::filesystem::is_symlink(file, error))
    record = provenance_beside(std::filesystem::canonical(file, error));
  if (!std::filesystem::exists(record, error)) {
    SIG_VERIFY(!state->deck, file.string()
                                 << " has no record of the deck it was made from ("
                                 << provenance_beside(file).string()
                                 << " is missing: written by an older Signorini, or copied in "
                                    "alone); rerun "
                                 << writer_of(kind) << " and the stages after it" << rerun_hint);
    note_case_input(kind, file, fingerprint, {});
    return;
  }
  const Ds ds = read_ds_record(record, kind);
  SIG_VERIFY(ds.has("fingerprint") && ds.text("fingerprint") == fingerprint_text(fingerprint),
             file.string() << " is not the " << kind << " that " << record.string()
                           << " records (fingerprint "
                           << (ds.has("fingerprint") ? ds.text("fingerprint") : "none")
                           << " there, " << fingerprint_text(fingerprint)
                           << " here): " << file.string()
                           << " was replaced or copied in after it was written; rerun "
                           << writer_of(kind) << " and the stages after it" << rerun_hint);
  note_case_input(kind, file, fingerprint,
                  ds.has("provenance") ? parse_provenance(ds.text("provenance"), record.string())
                                       : Provenance{});
}

void write_provenance_beside(const std::filesystem::path& file, const std::string& kind,
                             std::uint64_t fingerprint, const std::string& title,
                             const std::string& creator) {
  if (!current_case()) return;
  Ds record(kind, title, creator);
  record.put_text("fingerprint", fingerprint_text(fingerprint));
  record.put_text("describes", file.filename().string());
  write_ds(provenance_beside(file), record);
}

Provenance case_provenance(const std::string& kind) {
  Provenance provenance;
  std::optional<Case>& state = current_case();
  if (!state) return provenance;
  std::vector<ProvenanceEntry>& entries = provenance.inputs;
  for (const Statement& s : state->statements) {
    if (s.entry.kind == kind) continue;
    bool known = false;
    for (ProvenanceEntry& e : entries)
      if (e.kind == s.entry.kind) {
        known = true;
        if (s.direct()) e.file = s.entry.file; // the name this stage read it under
      }
    if (!known) entries.push_back(s.entry);
  }
  provenance.cards = state->cards;
  if (state->deck)
    for (const std::string& keyword : dependency_cards(stage_cards(state->stage)))
      if (std::none_of(provenance.cards.begin(), provenance.cards.end(),
                       [&](const CardRecord& known) { return known.keyword == keyword; }))
        provenance.cards.push_back(card_record(*state->deck, keyword));
  return provenance;
}

std::string provenance_text(const Provenance& provenance) {
  std::string text;
  for (const ProvenanceEntry& e : provenance.inputs)
    text += e.kind + " " + fingerprint_text(e.fingerprint) + " " + e.file + "\n";
  for (const CardRecord& c : provenance.cards)
    text += std::string(card_tag) + " " + c.keyword + " " + fingerprint_text(c.fingerprint) + " " +
            c.values + "\n";
  return text;
}

namespace {
bool is_fingerprint(const std::string& digits) {
  return digits.size() == 16 && digits.find_first_not_of("0123456789abcdef") == std::string::npos;
}
} // namespace

Provenance parse_provenance(const std::string& text, const std::string& file) {
  Provenance provenance;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const auto first = line.find(' ');
    if (first != std::string::npos && line.substr(0, first) == card_tag) {
      // CARD KEYWORD FINGERPRINT VALUES
      const auto second = line.find(' ', first + 1);
      const auto third = second == std::string::npos ? second : line.find(' ', second + 1);
      const std::string keyword =
          second == std::string::npos ? "" : line.substr(first + 1, second - first - 1);
      const std::string digits =
          third == std::string::npos ? "" : line.substr(second + 1, third - second - 1);
      SIG_VERIFY(!keyword.empty() && is_fingerprint(digits) && third + 1 < line.size(),
                 file << ": array 'provenance': bad line '" << line
                      << "' (expected CARD KEYWORD FINGERPRINT VALUES)");
      provenance.cards.push_back(
          {keyword, std::stoull(digits, nullptr, 16), line.substr(third + 1)});
      continue;
    }
    const auto second = first == std::string::npos ? first : line.find(' ', first + 1);
    const std::string digits =
        second == std::string::npos ? "" : line.substr(first + 1, second - first - 1);
    SIG_VERIFY(first > 0 && first <= 4 && is_fingerprint(digits) && second + 1 < line.size(),
               file << ": array 'provenance': bad line '" << line
                    << "' (expected KIND FINGERPRINT FILE)");
    provenance.inputs.push_back(
        {line.substr(0, first), std::stoull(digits, nullptr, 16), line.substr(second + 1)});
  }
  return provenance;
}

} // namespace sig
