#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/json.hpp"
#include "core/log.hpp"
#include "text_case.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace sig {

namespace {
bool is_space(char c) {
  return c == ' ' || c == '\t';
}
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::vector<std::string>& looked_up() {
  static std::vector<std::string> keywords;
  return keywords;
}

// The canonical spelling of a field of `spec` (case-insensitive match), or nullptr.
const char* find_field(const CardSpec& spec, const std::string& name) {
  for (const auto& field : spec.fields)
    if (to_lower(field.name) == name) return field.name;
  return nullptr;
}

std::string known_keywords() {
  std::string list;
  for (const auto& spec : card_schema())
    list.append(list.empty() ? "" : ", ").append(spec.keyword);
  return list;
}

std::string allowed_fields(const CardSpec& spec) {
  std::string list;
  for (const auto& field : spec.fields)
    list.append(list.empty() ? "" : ", ").append(field.name);
  return list;
}

// Cut the comment: '#' starts one anywhere outside double quotes.
std::string strip_comment(const std::string& raw, const std::string& file, int line) {
  bool quoted = false;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '"') quoted = !quoted;
    if (raw[i] == '#' && !quoted) return raw.substr(0, i);
  }
  if (quoted) throw InputError(file, line, "", "unterminated quote");
  return raw;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") + 1 - first);
}

// Fields after the keyword: `name=value`, `name = value`, `name="a b"`, lists `0,-2` (a space
// after a comma continues the list).
void parse_fields(Card& card, const CardSpec& spec, const std::string& rest) {
  std::size_t i = 0;
  const auto skip_spaces = [&] {
    while (i < rest.size() && is_space(rest[i]))
      ++i;
  };
  while (true) {
    skip_spaces();
    if (i == rest.size()) return;
    const std::size_t name_start = i;
    while (i < rest.size() && is_name_char(rest[i]))
      ++i;
    if (i == name_start) {
      std::size_t end = i;
      while (end < rest.size() && !is_space(rest[end]))
        ++end;
      throw InputError(card.file, card.line, "",
                       "expected name=value, got '" + rest.substr(name_start, end - name_start) +
                           "'");
    }
    const std::string written = rest.substr(name_start, i - name_start);
    const std::string name = to_lower(written);
    if (find_field(spec, name) == nullptr)
      card.fail(written,
                "unknown field for " + card.keyword + " (allowed: " + allowed_fields(spec) + ")");
    skip_spaces();
    if (i == rest.size() || rest[i] != '=') card.fail(written, "missing '=' after the field name");
    ++i;
    skip_spaces();
    std::string value;
    if (i < rest.size() && rest[i] == '"') {
      const auto close = rest.find('"', i + 1); // strip_comment checked it exists
      value = rest.substr(i + 1, close - i - 1);
      i = close + 1;
      if (i < rest.size() && !is_space(rest[i]))
        card.fail(written, "unexpected text after the closing quote");
    } else {
      while (i < rest.size()) {
        while (i < rest.size() && !is_space(rest[i]))
          value += rest[i++];
        if (value.empty() || value.back() != ',') break;
        skip_spaces();
      }
      if (value.empty()) card.fail(written, "missing value after '='");
      // `name= vtk=yes`: the value is empty and the next field follows; never take it as one.
      std::size_t name_end = 0;
      while (name_end < value.size() && is_name_char(value[name_end]))
        ++name_end;
      if (name_end > 0 && name_end < value.size() && value[name_end] == '=')
        card.fail(written,
                  "empty value ('" + value + "' is the next field); give a value after '='");
    }
    if (value.empty()) card.fail(written, "empty value; give a value after '='");
    if (card.has(name)) card.fail(written, "field given twice");
    card.fields.emplace_back(name, value);
  }
}

Card parse_card(const std::string& raw, const std::string& file, int line) {
  Card card;
  card.file = file;
  card.line = line;
  const std::string content = trim(strip_comment(raw, file, line));
  std::size_t end = 0;
  while (end < content.size() && !is_space(content[end]))
    ++end;
  card.keyword = to_upper(content.substr(0, end));
  const CardSpec* spec = find_card_spec(card.keyword);
  if (spec == nullptr)
    throw InputError(file, line, "",
                     "unknown card '" + content.substr(0, end) + "' (known: " + known_keywords() +
                         ")");
  const std::string rest = trim(content.substr(end));
  if (spec->fields.empty()) {
    // A free-text card (TITLE); surrounding quotes are optional.
    card.text_value = rest;
    if (rest.size() >= 2 && rest.front() == '"' && rest.back() == '"')
      card.text_value = rest.substr(1, rest.size() - 2);
    // Free text goes to JSON, VTK and DS headers: make it valid UTF-8, and say so.
    std::size_t replaced = 0;
    card.text_value = valid_utf8(card.text_value, &replaced);
    if (replaced > 0)
      log_warning(file + ":" + std::to_string(line) + ": " + card.keyword +
                  " is not valid UTF-8: " + std::to_string(replaced) +
                  " bad byte(s) replaced by U+FFFD");
  } else {
    parse_fields(card, *spec, rest);
  }
  return card;
}

std::string repeated_card_message(const Card& first, const Card& second) {
  return "card " + first.keyword + " given twice (lines " + std::to_string(first.line) + " and " +
         std::to_string(second.line) + "); only one is allowed";
}
} // namespace

const CardSpec* find_card_spec(const std::string& keyword) {
  const std::string key = to_upper(keyword);
  for (const auto& spec : card_schema())
    if (key == spec.keyword) return &spec;
  return nullptr;
}

const std::vector<std::string>& cards_looked_up() {
  return looked_up();
}

void forget_cards_looked_up() {
  looked_up().clear();
}

Datafile Datafile::read(const std::filesystem::path& path) {
  verify_regular_file(path, "datafile");
  std::ifstream in(path, std::ios::binary);
  SIG_VERIFY(in, path.string() << ": cannot read datafile: " << std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  SIG_VERIFY(!in.bad(), path.string() << ": read error");
  return parse(text.str(), path.string());
}

Datafile Datafile::parse(const std::string& text, const std::string& file_name) {
  Datafile deck;
  deck.path = file_name;
  // An editor's byte order mark is not a card.
  std::size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  int line = 0;
  while (start < text.size()) {
    // Lines end with LF, CR LF or CR alone (old Mac editors).
    const std::size_t end = text.find_first_of("\r\n", start);
    std::string raw = text.substr(start, end == std::string::npos ? end : end - start);
    start = end == std::string::npos                                              ? text.size()
            : text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? end + 2
                                                                                  : end + 1;
    ++line;
    if (trim(strip_comment(raw, file_name, line)).empty()) continue;
    Card card = parse_card(raw, file_name, line);
    if (!find_card_spec(card.keyword)->repeatable)
      for (const auto& earlier : deck.cards_)
        if (earlier.keyword == card.keyword)
          throw InputError(file_name, line, "", repeated_card_message(earlier, card));
    deck.cards_.push_back(std::move(card));
  }
  return deck;
}

std::vector<const Card*> Datafile::all(const std::string& keyword) const {
  const std::string key = to_upper(keyword);
  if (std::find(looked_up().begin(), looked_up().end(), key) == looked_up().end())
    looked_up().push_back(key);
  std::vector<const Card*> found;
  for (const auto& card : cards_)
    if (card.keyword == key) found.push_back(&card);
  return found;
}

const Card* Datafile::find(const std::string& keyword) const {
  const auto found = all(keyword);
  if (found.empty()) return nullptr;
  if (found.size() > 1)
    throw InputError(path, found[1]->line, "", repeated_card_message(*found[0], *found[1]));
  return found[0];
}

const Card& Datafile::require(const std::string& keyword) const {
  const Card* card = find(keyword);
  if (card == nullptr) throw InputError(path, 0, "", "missing card " + to_upper(keyword));
  return *card;
}

std::string Datafile::title() const {
  const Card* card = find("TITLE");
  return card != nullptr && !card->text_value.empty() ? card->text_value : stem();
}

std::string Datafile::stem() const {
  return std::filesystem::path(path).stem().string();
}

} // namespace sig
