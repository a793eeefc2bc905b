#include "core/json.hpp"

#include "core/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace sig {

namespace {
void write_string(std::string& out, const std::string& s) {
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
