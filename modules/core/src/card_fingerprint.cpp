#include "core/card_fingerprint.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/input_file.hpp"
#include "text_case.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace sig {

namespace {

constexpr const char* absent = "(absent)";
constexpr const char* no_fields = "(no fields)";
constexpr const char* separator = " | ";

// One card of the keyword: its canonical values and its line in the deck.
struct Instance {
  std::string text;
  int line = 0;
};

// Keywords whose later cards override earlier ones on shared nodes: their order is a value.
bool order_matters(const std::string& keyword) {
  return keyword == "DIRICHLET" || keyword == "INITIAL";
}

// Spaces and the separators stay out of a value, so that a record splits back into fields.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '%' || c == ' ' || c == '|' || c == '\t') {
      static constexpr char hex[] = "0123456789abcdef";
      out += '%';
      out += hex[(static_cast<unsigned char>(c) >> 4) & 0xf];
      out += hex[static_cast<unsigned char>(c) & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

// The canonical text of one number, or nothing if `item` is not one.
std::optional<std::string> canonical_number(std::string_view item) {
  if (item.size() > 1 && item.front() == '+' && item[1] != '+' && item[1] != '-')
    item.remove_prefix(1);
  const char* first = item.data();
  const char* last = item.data() + item.size();
  long integer = 0;
  if (const auto [end, error] = std::from_chars(first, last, integer);
      error == std::errc{} && end == last && !item.empty())
    return std::to_string(integer);
  double x = 0;
  const auto [end, error] = std::from_chars(first, last, x);
  if (error != std::errc{} || end != last || item.empty() || !std::isfinite(x)) return {};
  if (x == 0) x = 0; // -0 is 0
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, x);
  return std::string(text, written.ptr);
}

// A list of numbers item by item ("0, -2" and "0,-2.0" are "0,-2"), or nothing.
std::optional<std::string> canonical_numbers(const std::string& value) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = value.find(',', start);
    std::string item = value.substr(start, comma == std::string::npos ? comma : comma - start);
    const auto first = item.find_first_not_of(" \t");
    item = first == std::string::npos
               ? ""
               : item.substr(first, item.find_last_not_of(" \t") + 1 - first);
    const auto number = canonical_number(item);
    if (!number) return {};
    out += (out.empty() ? "" : ",") + *number;
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

// A mesh file is its contents: read in pieces (a large gmsh file), never a device.
std::string file_contents_value(const Card& card, const std::string& field) {
  const std::filesystem::path path = card.path(field);
  std::ifstream in(path, std::ios::binary);
  if (!not_a_regular_file(path).empty() || !in) return "unreadable:" + escaped(path.string());
  std::uint64_t hash = fnv1a64(nullptr, 0);
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    hash = fnv1a64(buffer, static_cast<std::size_t>(in.gcount()), hash);
  if (in.bad()) return "unreadable:" + escaped(path.string());
  return "content:" + fingerprint_text(hash);
}

std::string canonical_value(const Card& card, const std::string& field, const std::string& value) {
  if (card.keyword == "MESH" && field == "file") return file_contents_value(card, field);
  if (card.keyword == "OUTPUT" && field == "name") return escaped(value); // a file name: case kept
  if (const auto numbers = canonical_numbers(value)) return *numbers;
  return escaped(to_lower(value));
}

std::string canonical_card(const Card& card) {
  const CardSpec* spec = find_card_spec(card.keyword);
  if (spec != nullptr && spec->fields.empty()) return "text=" + escaped(card.text_value); // TITLE
  std::string out;
  if (spec != nullptr)
    for (const FieldSpec& field : spec->fields) {
      const std::string name = to_lower(field.name);
      if (renamed_field(card.keyword, name) != nullptr) continue; // counted under its new name
      auto given = std::find_if(card.fields.begin(), card.fields.end(),
                                [&](const auto& f) { return f.first == name; });
      if (given == card.fields.end())
        given = std::find_if(card.fields.begin(), card.fields.end(), [&](const auto& f) {
          const char* renamed = renamed_field(card.keyword, f.first);
          return renamed != nullptr && renamed == name;
        });
      if (given == card.fields.end() && field.fallback == nullptr) continue;
      const std::string value = given != card.fields.end() ? given->second : field.fallback;
      if (!out.empty()) out += ' ';
      out.append(field.name).append("=").append(canonical_value(card, name, value));
    }
  return out.empty() ? no_fields : out;
}

std::vector<Instance> instances(const Datafile& deck, const std::string& keyword) {
  std::vector<Instance> found;
  for (const Card& card : deck.cards())
    if (card.keyword == keyword) found.push_back({canonical_card(card), card.line});
  if (!order_matters(keyword))
    std::stable_sort(found.begin(), found.end(),
                     [](const Instance& a, const Instance& b) { return a.text < b.text; });
  return found;
}

std::string joined(const std::vector<Instance>& cards) {
  if (cards.empty()) return absent;
  std::string out;
  for (const Instance& card : cards)
    out += (out.empty() ? "" : separator) + card.text;
  return out;
}

std::vector<std::string> split(const std::string& text, const std::string& by) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(by, start);
    parts.push_back(text.substr(start, at == std::string::npos ? at : at - start));
    if (at == std::string::npos) return parts;
    start = at + by.size();
  }
}

// The value as the user wrote it, for messages.
std::string unescaped(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() &&
        std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

using Fields = std::vector<std::pair<std::string, std::string>>;

Fields fields_of(const std::string& instance) {
  Fields fields;
  if (instance == no_fields) return fields;
  for (const std::string& token : split(instance, " ")) {
    const auto equals = token.find('=');
    fields.emplace_back(token.substr(0, equals),
                        equals == std::string::npos ? "" : token.substr(equals + 1));
  }
  return fields;
}

std::string value_in(const Fields& fields, const std::string& name) {
  for (const auto& [field, value] : fields)
    if (field == name) return unescaped(value);
  return "(not given)";
}

// "KEY a=1 b=2" of the fields that differ between two cards of one keyword, on either side; a
// repeatable card keeps the field that says which one it is (ref=, region=).
std::pair<std::string, std::string>
differing_fields(const std::string& keyword, const std::string& before, const std::string& after) {
  const Fields old_fields = fields_of(before), new_fields = fields_of(after);
  std::vector<std::string> names;
  for (const Fields* fields : {&old_fields, &new_fields})
    for (const auto& [name, value] : *fields)
      if (value_in(old_fields, name) != value_in(new_fields, name) &&
          std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
  const CardSpec* spec = find_card_spec(keyword);
  for (const char* id : {"region", "ref"})
    if (spec != nullptr && spec->repeatable &&
        std::find(names.begin(), names.end(), id) == names.end() &&
        value_in(old_fields, id) == value_in(new_fields, id) &&
        value_in(old_fields, id) != "(not given)")
      names.insert(names.begin(), id);
  std::string old_text = keyword, new_text = keyword;
  for (const std::string& name : names) {
    old_text += " " + name + "=" + value_in(old_fields, name);
    new_text += " " + name + "=" + value_in(new_fields, name);
  }
  return {old_text, new_text};
}

// "(line 5)", "(lines 5, 9)".
std::string lines_of(const std::vector<Instance>& cards) {
  std::string out = cards.size() == 1 ? "(line " : "(lines ";
  for (const Instance& card : cards)
    out += (&card == &cards.front() ? "" : ", ") + std::to_string(card.line);
  return out + ")";
}

} // namespace

CardRecord card_record(const Datafile& deck, const std::string& keyword) {
  const std::string key = to_upper(keyword);
  CardRecord record{key, 0, joined(instances(deck, key))};
  record.fingerprint = fnv1a64(record.values.data(), record.values.size());
  return record;
}

std::string card_change(const CardRecord& recorded, const Datafile& deck) {
  const std::vector<Instance> now = instances(deck, recorded.keyword);
  const std::string now_values = joined(now);
  if (fnv1a64(now_values.data(), now_values.size()) == recorded.fingerprint) return "";
  const std::string& key = recorded.keyword;
  const std::vector<std::string> before =
      recorded.values == absent ? std::vector<std::string>{} : split(recorded.values, separator);
  const std::string where = deck.path + ":";
  if (before.empty()) {
    if (now.size() == 1)
      return "without a " + key + " card, but " + where + std::to_string(now[0].line) +
             " now has " + key + " " + now[0].text;
    return "without a " + key + " card, but " + deck.path + " now has " +
           std::to_string(now.size()) + " " + key + " cards " + lines_of(now);
  }
  if (now.empty())
    return "with " + key + " " + recorded.values + ", but " + deck.path + " has no " + key +
           " card now";
  if (before.size() != now.size())
    return "with " + std::to_string(before.size()) + " " + key + " cards, but " + deck.path +
           " now has " + std::to_string(now.size()) + " " + lines_of(now);
  std::size_t k = 0;
  while (k + 1 < now.size() && before[k] == now[k].text)
    ++k;
  if (before[k] == now[k].text) // a record made by another version of the canonical text
    return "with " + key + " " + recorded.values + ", which " + deck.path +
           " gives in other words (the record is of an older Signorini)";
  const auto [old_text, new_text] = differing_fields(key, before[k], now[k].text);
  return "with " + old_text + ", but " + where + std::to_string(now[k].line) + " now says " +
         new_text;
}

} // namespace sig
