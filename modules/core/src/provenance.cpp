#include "core/provenance.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"

#include <optional>
#include <sstream>

namespace sig {

namespace {

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

} // namespace

void open_case(const std::filesystem::path& outdir) {
  current_case() = Case{folder_of(outdir / "x"), {}};
}

void close_case() {
  current_case().reset();
}

std::filesystem::path case_folder() {
  return current_case() ? current_case()->folder : std::filesystem::path();
}

void note_case_input(const std::string& kind, const std::filesystem::path& file,
                     std::uint64_t fingerprint, const std::vector<ProvenanceEntry>& built_from) {
  std::optional<Case>& state = current_case();
  if (!state || folder_of(file) != state->folder) return;
  std::vector<Statement> fresh{{{kind, fingerprint, file.string()}, file.string()}};
  for (const ProvenanceEntry& entry : built_from)
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
  state->statements.insert(state->statements.end(), fresh.begin(), fresh.end());
}

std::vector<ProvenanceEntry> case_provenance(const std::string& kind) {
  std::vector<ProvenanceEntry> entries;
  const std::optional<Case>& state = current_case();
  if (!state) return entries;
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
  return entries;
}

std::string provenance_text(const std::vector<ProvenanceEntry>& entries) {
  std::string text;
  for (const ProvenanceEntry& e : entries)
    text += e.kind + " " + fingerprint_text(e.fingerprint) + " " + e.file + "\n";
  return text;
}

std::vector<ProvenanceEntry> parse_provenance(const std::string& text, const std::string& file) {
  std::vector<ProvenanceEntry> entries;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const auto first = line.find(' ');
    const auto second = first == std::string::npos ? first : line.find(' ', first + 1);
    const std::string digits =
        second == std::string::npos ? "" : line.substr(first + 1, second - first - 1);
    SIG_VERIFY(first > 0 && first <= 4 && digits.size() == 16 &&
                   digits.find_first_not_of("0123456789abcdef") == std::string::npos &&
                   second + 1 < line.size(),
               file << ": array 'provenance': bad line '" << line
                    << "' (expected KIND FINGERPRINT FILE)");
    entries.push_back(
        {line.substr(0, first), std::stoull(digits, nullptr, 16), line.substr(second + 1)});
  }
  return entries;
}

} // namespace sig
