#include "core/card_help.hpp"

#include <algorithm>
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

} // namespace sig
