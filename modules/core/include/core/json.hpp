#pragma once
// A small JSON writer for summary.json and sig-dump --json: keys keep insertion order so the
// output is stable for scripts and diffs; strings are written as valid UTF-8 whatever they hold.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace sig {

/// `text` with every byte that is not part of a well-formed UTF-8 sequence replaced by U+FFFD;
/// `replaced` (if given) counts them. JSON output is always valid UTF-8 this way.
std::string valid_utf8(const std::string& text, std::size_t* replaced = nullptr);

class Json {
public:
  using Object = std::vector<std::pair<std::string, Json>>;
  using Array = std::vector<Json>;

  Json() : value_(nullptr) {}
  Json(std::nullptr_t) : value_(nullptr) {}
  Json(bool b) : value_(b) {}
  Json(int i) : value_(static_cast<double>(i)) {}
  Json(long i) : value_(static_cast<double>(i)) {}
  Json(long long i) : value_(static_cast<double>(i)) {}
  Json(unsigned long i) : value_(static_cast<double>(i)) {}
  Json(double d) : value_(d) {}
  Json(const char* s) : value_(std::string(s)) {}
  Json(std::string s) : value_(std::move(s)) {}
  Json(Array a) : value_(std::move(a)) {}
  Json(Object o) : value_(std::move(o)) {}
  template <class T> static Json array_of(const std::vector<T>& v) {
    Array a;
    for (const auto& x : v)
      a.emplace_back(x);
    return Json(std::move(a));
  }
  static Json object() { return Json(Object{}); }

  /// Set (or replace) a key of an object.
  Json& set(const std::string& key, Json value);
  /// Serialize; indent < 0 gives one line. Non-finite numbers are written as null.
  std::string dump(int indent = 2) const;

private:
  void write(std::string& out, int indent, int depth) const;
  std::variant<std::nullptr_t, bool, double, std::string, Array, Object> value_;
};

} // namespace sig
