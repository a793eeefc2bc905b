#pragma once
// The datafile: one card per line, `KEYWORD name=value ...`, `#` starts a comment, keywords and
// field names are case-insensitive, lists are written `0,-2`, a value with spaces is quoted.
// `TITLE` takes the rest of its line as free text. Every card and field is declared once in the
// card schema (cards.cpp); reading rejects unknown cards and fields, and every error thrown from a
// Card names the file, the line and the field. A field's number is checked against its range
// (core/ranges.hpp) when read; an empty value is an error (`name= vtk=yes` never takes
// 'vtk=yes' as the name). Lines end with LF, CR LF or CR; a UTF-8 byte order mark is skipped; a
// TITLE that is not UTF-8 has its bad bytes replaced (with a warning), so outputs stay valid.
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sig {

class Card {
public:
  std::string keyword; ///< upper case
  std::string file;
  int line = 0;
  std::vector<std::pair<std::string, std::string>> fields; ///< lower-case names, in order
  std::string text_value;                                  ///< free text (TITLE)

  // Field names given to the accessors are case-insensitive ("E" and "e" are the same field).
  // An accessor without a fallback returns the schema's default of an absent field (FieldSpec::
  // fallback) and fails naming the field when the schema has none: the field is required.
  bool has(const std::string& name) const; ///< given in the deck (a schema default is not)
  std::string text(const std::string& name) const;
  std::string text(const std::string& name, const std::string& fallback) const;
  double real(const std::string& name) const;
  double real(const std::string& name, double fallback) const;
  long integer(const std::string& name) const;
  long integer(const std::string& name, long fallback) const;
  std::vector<double> reals(const std::string& name) const; ///< "1,-2.5"
  std::vector<long> integers(const std::string& name) const;
  /// A file name (required field); a relative one is taken from the datafile's folder.
  std::filesystem::path path(const std::string& name) const;
  /// A plain file name for an output (letters, digits, . _ + -, not starting with '.': no
  /// folder, never hidden); `fallback` when the field is absent.
  std::string file_name(const std::string& name, const std::string& fallback) const;
  /// One of `allowed` (case-insensitive, returned lower case).
  std::string choice(const std::string& name, std::initializer_list<const char*> allowed) const;
  std::string choice(const std::string& name, std::initializer_list<const char*> allowed,
                     const std::string& fallback) const;
  /// Throw InputError(file, line, name, what), the field spelt as in the card schema.
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;
};

class Datafile {
public:
  static Datafile read(const std::filesystem::path& path);
  static Datafile parse(const std::string& text, const std::string& file_name);

  std::string path;
  const std::vector<Card>& cards() const { return cards_; }
  std::vector<const Card*> all(const std::string& keyword) const;
  const Card* find(const std::string& keyword) const;    ///< nullptr if absent; error if repeated
  const Card& require(const std::string& keyword) const; ///< error naming the file if absent
  std::string title() const;                             ///< TITLE text or the file stem
  std::string stem() const;

private:
  std::vector<Card> cards_;
};

struct FieldSpec {
  FieldSpec(const char* name, const char* help, const char* fallback = nullptr)
      : name(name), help(help), fallback(fallback) {}
  const char* name;
  const char* help;
  /// The value an absent field takes (nullptr: none). Card::text, real, ... without a fallback
  /// return it, and --help shows it, so a default is written once, here.
  const char* fallback;
};
struct CardSpec {
  const char* keyword;
  bool repeatable;
  const char* help;
  std::vector<FieldSpec> fields;
};
/// Every card any stage reads, with its fields and help text (the card reference,
/// datafiles/CARDS.md).
const std::vector<CardSpec>& card_schema();
/// The schema of a card (keyword case-insensitive), nullptr if there is none.
const CardSpec* find_card_spec(const std::string& keyword);
/// The field that `field` of card `keyword` is an old spelling of (MESH center: "centre",
/// CONTACT gap: "g"), nullptr if it is none; both lower case.
const char* renamed_field(const std::string& keyword, const std::string& field);

/// The keywords this process has looked up in any datafile (Datafile::all, find, require,
/// title) since the last stage ended, upper case: what a stage reads, which its --help must list
/// (the test suite checks it through SIG_CARD_TRACE, see stage.hpp).
const std::vector<std::string>& cards_looked_up();
/// Forgets them: run_stage does at a stage's end, so that the next stage in the same process (the
/// adaptive loop, sig-adapt) is traced with its own.
void forget_cards_looked_up();

} // namespace sig
