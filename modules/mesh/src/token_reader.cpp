#include "token_reader.hpp"

#include "core/error.hpp"

#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>

namespace sig {

TokenReader::TokenReader(const std::filesystem::path& path) : file_(path.string()) {
  std::ifstream in(path, std::ios::binary);
  SIG_VERIFY(in, file_ << ": cannot open the mesh file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  SIG_VERIFY(!in.bad(), file_ << ": read error");
  text_ = buffer.str();
}

void TokenReader::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++scan_line_;
    } else if (c != ' ' && c != '\t' && c != '\r' && c != '\f' && c != '\v') {
      return;
    }
    ++pos_;
  }
}

bool TokenReader::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

std::string_view TokenReader::word() {
  skip_space();
  line_ = scan_line_;
  if (pos_ >= text_.size()) fail("unexpected end of file");
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])))
    ++pos_;
  return std::string_view(text_).substr(start, pos_ - start);
}

long TokenReader::integer() {
  const std::string_view token = word();
  long value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size())
    fail("expected an integer, found '" + std::string(token) + "'");
  return value;
}

double TokenReader::real() {
  std::string_view token = word();
  // from_chars refuses a leading '+'; skip one, but not a second sign ("+-3").
  if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+')
    token.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size())
    fail("expected a number, found '" + std::string(token) + "'");
  return value;
}

void TokenReader::expect(std::string_view token) {
  const std::string_view found = word();
  if (found != token)
    fail("expected '" + std::string(token) + "', found '" + std::string(found) + "'");
}

void TokenReader::skip_past(std::string_view end_token) {
  while (!at_end()) {
    if (word() == end_token) return;
  }
  fail("missing '" + std::string(end_token) + "'");
}

void TokenReader::fail(const std::string& what) const {
  throw InputError(file_, line_, "", what);
}

} // namespace sig
