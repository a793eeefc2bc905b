#include "core/card_help.hpp"

#include "core/ranges.hpp"
#include "text_case.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace sig {

std::string wrap_text(const std::string& text, std::size_t start, std::size_t indent,
                      std::size_t width) {
  std::istringstream words(text);
  std::string word, out, line;
  std::size_t column = start; // where `line` starts
  while (words >> word) {
    if (!line.empty() && column + line.size() + 1 + word.size() > width) {
      out += line + "\n" + std::string(indent, ' ');
      line.clear();
      column = indent;
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line + "\n";
}

std::string card_help(const CardSpec& spec) {
  std::string out = wrap_text(
      std::string(spec.keyword) + (spec.repeatable ? " (repeatable): " : ": ") + spec.help, 0, 4);
  std::size_t name_width = 0;
  for (const FieldSpec& field : spec.fields)
    name_width = std::max(name_width, std::string(field.name).size());
  for (const FieldSpec& field : spec.fields) {
    std::string name = field.name;
    name.resize(name_width, ' ');
    std::string text = field.help;
    if (field.fallback != nullptr) text += std::string(" [default: ") + field.fallback + "]";
    out += "    " + name + "  " + wrap_text(text, 6 + name_width, 6 + name_width);
  }
  return out;
}

std::string card_index() {
  std::size_t width = 0;
  for (const CardSpec& spec : card_schema())
    width = std::max(width, std::string(spec.keyword).size());
  std::string out;
  for (const CardSpec& spec : card_schema()) {
    std::string keyword = spec.keyword;
    keyword.resize(width, ' ');
    out += "  " + keyword + "  " + wrap_text(spec.help, 4 + width, 4 + width);
  }
  return out;
}

namespace {

// A word that would open a list, a quote, a heading or a table row at the start of a line
// ("- 3", "> 0", "# x", "1.", "| y"): wrapped Markdown must not begin a line with it.
bool opens_a_block(const std::string& word) {
  if (word.empty()) return false;
  if (std::string("-+*>#=|").find(word.front()) != std::string::npos) return true;
  const std::size_t digits = word.find_first_not_of("0123456789");
  return digits > 0 && digits != std::string::npos && digits + 1 == word.size() &&
         (word.back() == '.' || word.back() == ')');
}

// wrap_text for Markdown: lines end by column 100, continuation lines are indented by `indent`
// spaces, and a word that opens a block stays on the line before it.
std::string wrap_markdown(const std::string& text, std::size_t indent) {
  std::istringstream words(text);
  std::vector<std::string> units; // words, each block opener glued to the word before it
  for (std::string word; words >> word;) {
    if (!units.empty() && opens_a_block(word))
      units.back() += " " + word;
    else
      units.push_back(word);
  }
  std::string out, line;
  for (const std::string& unit : units) {
    const std::size_t start = out.empty() ? 0 : indent;
    if (!line.empty() && start + line.size() + 1 + unit.size() > 100) {
      out += (out.empty() ? "" : std::string(indent, ' ')) + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + unit;
  }
  return out + (out.empty() ? "" : std::string(indent, ' ')) + line + "\n";
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The heading anchor GitHub gives "## KEYWORD": the keyword in lower case. (Built by append:
// GCC 12 warns falsely, -Wrestrict, about "#" + std::string&&.)
std::string anchor(const std::string& keyword) {
  std::string link = "#";
  link += to_lower(keyword);
  return link;
}

// "- `name` (default `x`; range > 0): help", wrapped with continuation lines indented by two
// spaces so that they stay inside the list item.
std::string field_item(const CardSpec& spec, const FieldSpec& field) {
  std::string facts;
  if (field.fallback != nullptr) facts += std::string("default `") + field.fallback + "`";
  if (const ValueRange* range = field_range(spec.keyword, field.name))
    facts += (facts.empty() ? "range " : "; range ") + range->text();
  const std::string head = std::string("- `") + field.name + "`" +
                           (facts.empty() ? "" : " (" + facts + ")") + ": " + field.help;
  return wrap_markdown(head, 2);
}

} // namespace

std::string card_reference_markdown() {
  std::string out =
      "# Card reference\n\n" +
      wrap_markdown(
          "Generated from the card schema (`modules/core/src/cards.cpp`) and the table of "
          "ranges (`modules/core/src/ranges.cpp`) by `sig-dump --cards-markdown`: do not "
          "edit, regenerate it from the repository's root with",
          0) +
      "\n```sh\nbuild/bin/sig-dump --cards-markdown > datafiles/CARDS.md\n```\n\n" +
      wrap_markdown(
          "(the test `pipeline.cards_reference` fails while the two differ). A datafile has "
          "one card per line, `KEYWORD name=value ...`; `#` starts a comment; keywords and "
          "field names are case-insensitive; lists are written `0,-2`; a value with spaces "
          "is quoted. A field shown without a default is required, or its default depends on "
          "the deck, as its text says. A range is checked when a stage reads the field; every "
          "real number of a deck is 0 or of a magnitude in [" +
              number_text(kSmallestMagnitude) + ", " + number_text(kLargestMagnitude) +
              "]. The contact laws' parameters (`cn`, `c3`, `g`, `mu`, `threshold`, `a`, `b`, "
              "`alpha`) have their ranges with the laws (`modules/contact/laws`).",
          0) +
      "\n## Cards\n\n";
  for (const CardSpec& spec : card_schema())
    out += wrap_markdown(std::string("- [`") + spec.keyword + "`](" + anchor(spec.keyword) + ")" +
                             (spec.repeatable ? " (repeatable)" : "") + ": " + spec.help,
                         2);
  for (const CardSpec& spec : card_schema()) {
    out += std::string("\n## ") + spec.keyword + "\n\n";
    out += wrap_markdown(
        (spec.repeatable ? std::string("Repeatable. ") : std::string()) +
            static_cast<char>(std::toupper(static_cast<unsigned char>(spec.help[0]))) +
            (spec.help + 1) + ".",
        0);
    if (!spec.fields.empty()) out += "\n";
    for (const FieldSpec& field : spec.fields)
      out += field_item(spec, field);
  }
  return out;
}

} // namespace sig
