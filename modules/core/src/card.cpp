#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/ranges.hpp"
#include "text_case.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

namespace sig {

namespace {
const std::string* find_value(const Card& card, const std::string& name) {
  const std::string key = to_lower(name);
  for (const auto& [field, value] : card.fields)
    if (field == key) return &value;
  return nullptr;
}

// A number must fill the whole token and be finite: "1e3" and "-2.5" are numbers, "3 m", "nan"
// and "1e999" are not.
double parse_real(const Card& card, const std::string& name, const std::string& text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  // from_chars refuses a leading '+'; skip one, but not a second sign ("+-3").
  if (first != last && *first == '+' && (first + 1 == last || (first[1] != '-' && first[1] != '+')))
    ++first;
  double x = 0;
  const auto [end, error] = std::from_chars(first, last, x);
  if (error == std::errc::result_out_of_range)
    card.fail(name, "number out of range: '" + text + "'");
  if (error != std::errc() || end != last || text.empty())
    card.fail(name, "expected a number, got '" + text + "'");
  if (!std::isfinite(x)) card.fail(name, "expected a finite number, got '" + text + "'");
  if (const std::string excess = magnitude_excess(x); !excess.empty()) card.fail(name, excess);
  // -0 is 0: a value handed on as text (gmsh's -setnumber) must not read "-0".
  return x == 0 ? 0.0 : x;
}

// The range of the field (core/ranges.hpp), checked on every value a stage reads.
template <class T> T in_range(const Card& card, const std::string& name, T value) {
  const ValueRange* range = field_range(card.keyword, name);
  if (range != nullptr && !range->contains(static_cast<double>(value))) {
    std::ostringstream what;
    what << "must be " << range->text() << ", got " << value;
    if (range->why != nullptr) what << " (" << range->why << ")";
    card.fail(name, what.str());
  }
  return value;
}

long parse_integer(const Card& card, const std::string& name, const std::string& text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  // from_chars refuses a leading '+'; skip one, but not a second sign ("+-3").
  if (first != last && *first == '+' && (first + 1 == last || (first[1] != '-' && first[1] != '+')))
    ++first;
  long n = 0;
  const auto [end, error] = std::from_chars(first, last, n);
  if (error == std::errc::result_out_of_range)
    card.fail(name, "integer out of range: '" + text + "'");
  if (error != std::errc() || end != last || text.empty())
    card.fail(name, "expected an integer, got '" + text + "'");
  return n;
}

std::vector<std::string> split_list(const Card& card, const std::string& name,
                                    const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    const auto first = item.find_first_not_of(" \t");
    item = first == std::string::npos
               ? ""
               : item.substr(first, item.find_last_not_of(" \t") + 1 - first);
    if (item.empty()) card.fail(name, "empty item in the list '" + text + "'");
    items.push_back(item);
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

// The schema's default of a field, nullptr when it has none (or the card is not in the schema).
const char* schema_fallback(const std::string& keyword, const std::string& name) {
  const CardSpec* spec = find_card_spec(keyword);
  if (spec == nullptr) return nullptr;
  const std::string key = to_lower(name);
  for (const FieldSpec& field : spec->fields)
    if (to_lower(field.name) == key) return field.fallback;
  return nullptr;
}

std::string allowed_list(std::initializer_list<const char*> allowed) {
  std::string list;
  for (const char* a : allowed)
    list.append(list.empty() ? "" : "|").append(a);
  return list;
}
} // namespace

bool Card::has(const std::string& name) const {
  return find_value(*this, name) != nullptr;
}

std::string Card::text(const std::string& name) const {
  if (const std::string* value = find_value(*this, name)) return *value;
  if (const char* fallback = schema_fallback(keyword, name)) return fallback;
  fail(name, "missing (required by " + keyword + ")");
}

std::string Card::text(const std::string& name, const std::string& fallback) const {
  const std::string* value = find_value(*this, name);
  return value == nullptr ? fallback : *value;
}

double Card::real(const std::string& name) const {
  return in_range(*this, name, parse_real(*this, name, text(name)));
}

double Card::real(const std::string& name, double fallback) const {
  return has(name) ? real(name) : fallback;
}

long Card::integer(const std::string& name) const {
  return in_range(*this, name, parse_integer(*this, name, text(name)));
}

long Card::integer(const std::string& name, long fallback) const {
  return has(name) ? integer(name) : fallback;
}

std::vector<double> Card::reals(const std::string& name) const {
  std::vector<double> values;
  for (const auto& item : split_list(*this, name, text(name)))
    values.push_back(in_range(*this, name, parse_real(*this, name, item)));
  return values;
}

std::vector<long> Card::integers(const std::string& name) const {
  std::vector<long> values;
  for (const auto& item : split_list(*this, name, text(name)))
    values.push_back(in_range(*this, name, parse_integer(*this, name, item)));
  return values;
}

std::filesystem::path Card::path(const std::string& name) const {
  const std::filesystem::path given = text(name);
  if (given.empty()) fail(name, "empty file name");
  return given.is_absolute() ? given : std::filesystem::path(file).parent_path() / given;
}

std::string Card::file_name(const std::string& name, const std::string& fallback) const {
  if (!has(name)) return fallback;
  const std::string value = text(name);
  const bool plain = !value.empty() && value.size() <= 200 && value.front() != '.' &&
                     value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                             "0123456789._+-") == std::string::npos;
  if (!plain)
    fail(name, "'" + value +
                   "' is not a plain file name: letters, digits, '.', '_', '+' and '-', not "
                   "starting with '.' (no folder: the files go to the output folder)");
  return value;
}

std::string Card::choice(const std::string& name,
                         std::initializer_list<const char*> allowed) const {
  const std::string value = to_lower(text(name));
  for (const char* a : allowed)
    if (value == to_lower(a)) return value;
  fail(name, "expected one of " + allowed_list(allowed) + ", got '" + text(name) + "'");
}

std::string Card::choice(const std::string& name, std::initializer_list<const char*> allowed,
                         const std::string& fallback) const {
  return has(name) ? choice(name, allowed) : fallback;
}

void Card::fail(const std::string& name, const std::string& what) const {
  // The field as the schema spells it ('R', 'N'), whatever case the code asked for it in.
  if (const CardSpec* spec = find_card_spec(keyword))
    for (const FieldSpec& field : spec->fields)
      if (to_lower(field.name) == to_lower(name)) throw InputError(file, line, field.name, what);
  throw InputError(file, line, name, what);
}

} // namespace sig
