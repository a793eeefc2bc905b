#include "core/json.hpp"

#include "core/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace sig {

namespace {
// Length of the well-formed UTF-8 sequence at p (RFC 3629: no overlong forms, no surrogates, at
// most U+10FFFF), or 0.
std::size_t utf8_sequence(const unsigned char* p, std::size_t left) {
  const unsigned char c = p[0];
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) low = 0xA0;
    if (c == 0xED) high = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) low = 0x90;
    if (c == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (left < n || p[1] < low || p[1] > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (p[k] < 0x80 || p[k] > 0xBF) return 0;
  return n;
}

void write_string(std::string& out, const std::string& text) {
  const std::string s = valid_utf8(text);
  out += '"';
  for (const char ch : s) {
    switch (ch) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\b':
      out += "\\b";
      break;
    case '\f':
      out += "\\f";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\r':
      out += "\\r";
      break;
    case '\t':
      out += "\\t";
      break;
    default:
      if (static_cast<unsigned char>(ch) < 0x20) {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(ch));
        out += escape;
      } else {
        out += ch; // UTF-8 passes through unchanged
      }
    }
  }
  out += '"';
}

// Integral values print as integers (counts, iterations); others in the shortest form that reads
// back to the same double (at most 17 significant digits).
void write_number(std::string& out, double x) {
  if (!std::isfinite(x)) {
    out += "null";
    return;
  }
  char text[32];
  if (x == std::trunc(x) && std::fabs(x) < 1e15) {
    std::snprintf(text, sizeof text, "%lld", static_cast<long long>(x));
    out += text;
    return;
  }
  const auto result = std::to_chars(text, text + sizeof text, x);
  out.append(text, result.ptr);
}

void newline(std::string& out, int indent, int depth) {
  if (indent < 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}
} // namespace

std::string valid_utf8(const std::string& text, std::size_t* replaced) {
  std::string out;
  out.reserve(text.size());
  std::size_t bad = 0;
  const auto* p = reinterpret_cast<const unsigned char*>(text.data());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence(p + i, text.size() - i);
    if (n == 0) {
      out += "\xEF\xBF\xBD"; // U+FFFD REPLACEMENT CHARACTER
      ++bad;
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  if (replaced != nullptr) *replaced = bad;
  return out;
}

Json& Json::set(const std::string& key, Json value) {
  auto* object = std::get_if<Object>(&value_);
  SIG_VERIFY(object != nullptr, "Json::set('" << key << "') on a value that is not an object");
  for (auto& [k, v] : *object)
    if (k == key) {
      v = std::move(value);
      return *this;
    }
  object->emplace_back(key, std::move(value));
  return *this;
}

std::string Json::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  return out;
}

void Json::write(std::string& out, int indent, int depth) const {
  if (std::holds_alternative<std::nullptr_t>(value_)) {
    out += "null";
  } else if (const auto* b = std::get_if<bool>(&value_)) {
    out += *b ? "true" : "false";
  } else if (const auto* x = std::get_if<double>(&value_)) {
    write_number(out, *x);
  } else if (const auto* s = std::get_if<std::string>(&value_)) {
    write_string(out, *s);
  } else if (const auto* a = std::get_if<Array>(&value_)) {
    if (a->empty()) {
      out += "[]";
      return;
    }
    out += '[';
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i > 0) out += ',';
      newline(out, indent, depth + 1);
      (*a)[i].write(out, indent, depth + 1);
    }
    newline(out, indent, depth);
    out += ']';
  } else if (const auto* o = std::get_if<Object>(&value_)) {
    if (o->empty()) {
      out += "{}";
      return;
    }
    out += '{';
    for (std::size_t i = 0; i < o->size(); ++i) {
      if (i > 0) out += ',';
      newline(out, indent, depth + 1);
      write_string(out, (*o)[i].first);
      out += indent < 0 ? ":" : ": ";
      (*o)[i].second.write(out, indent, depth + 1);
    }
    newline(out, indent, depth);
    out += '}';
  }
}

} // namespace sig
