#include "token_reader.hpp"

#include "core/error.hpp"
#include "core/input_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sig {

namespace {
// No number or keyword of a mesh file is longer; a longer "token" is binary data or garbage,
// and is refused before it fills the memory.
constexpr std::size_t max_token = 256;
constexpr std::size_t buffer_size = 1 << 16;

bool is_space(int c) {
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
} // namespace

TokenReader::TokenReader(const std::filesystem::path& path) : file_(path.string()) {
  verify_regular_file(path, "mesh file");
  std::error_code error;
  size_ = std::filesystem::file_size(path, error);
  SIG_VERIFY(!error, file_ << ": cannot open the mesh file: " << error.message());
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  SIG_VERIFY(*in, file_ << ": cannot open the mesh file");
  in_ = std::move(in);
  buffer_.resize(buffer_size);
}

TokenReader::TokenReader(std::string name, std::string contents) : file_(std::move(name)) {
  size_ = contents.size();
  in_ = std::make_unique<std::istringstream>(std::move(contents));
  buffer_.resize(buffer_size);
}

bool TokenReader::fill() {
  if (begin_ < end_) return true;
  in_->read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  begin_ = 0;
  end_ = static_cast<std::size_t>(in_->gcount());
  SIG_VERIFY(end_ > 0 || !in_->bad(), file_ << ": read error");
  return end_ > 0;
}

int TokenReader::peek() {
  return fill() ? static_cast<unsigned char>(buffer_[begin_]) : -1;
}

int TokenReader::get() {
  if (!fill()) return -1;
  const int c = static_cast<unsigned char>(buffer_[begin_++]);
  ++offset_;
  if (c == '\n') ++scan_line_;
  return c;
}

bool TokenReader::at_end() {
  while (is_space(peek()))
    get();
  return peek() < 0;
}

std::string_view TokenReader::word() {
  // Fast path: the blanks skipped and the token taken within the buffer, the token returned as a
  // view into it (valid, as token_ is, until the next call); a token that reaches the buffer's end
  // (or is too long) takes the character-wise path below.
  while (fill()) {
    while (begin_ < end_ && is_space(static_cast<unsigned char>(buffer_[begin_]))) {
      if (buffer_[begin_] == '\n') ++scan_line_;
      ++begin_;
      ++offset_;
    }
    if (begin_ < end_) break;
  }
  if (begin_ < end_) {
    std::size_t stop = begin_;
    while (stop < end_ && stop - begin_ < max_token &&
           !is_space(static_cast<unsigned char>(buffer_[stop])))
      ++stop;
    if (stop < end_ && is_space(static_cast<unsigned char>(buffer_[stop]))) {
      line_ = scan_line_;
      const std::string_view token(buffer_.data() + begin_, stop - begin_);
      offset_ += stop - begin_;
      begin_ = stop;
      return token;
    }
  }
  if (at_end()) {
    line_ = scan_line_;
    fail("unexpected end of file");
  }
  line_ = scan_line_;
  token_.clear();
  while (peek() >= 0 && !is_space(peek())) {
    if (token_.size() == max_token)
      fail("a token of more than " + std::to_string(max_token) +
           " characters: binary data or garbage where text was expected");
    token_ += static_cast<char>(get());
  }
  return token_;
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
  if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
    fail("expected a finite number, found '" + std::string(token) + "'");
  return value;
}

void TokenReader::expect(std::string_view token) {
  const std::string found(word());
  if (found != token) fail("expected '" + std::string(token) + "', found '" + found + "'");
}

void TokenReader::skip_past(std::string_view end_token) {
  // Byte by byte, so binary data in the section is skipped too: the end marker starts a line.
  std::size_t matched = 0;
  bool line_start = true;
  const int first_line = line_;
  while (true) {
    const int c = get();
    if (c < 0) {
      line_ = first_line;
      fail("missing '" + std::string(end_token) + "'");
    }
    if (matched < end_token.size() && (matched > 0 || line_start) &&
        c == static_cast<unsigned char>(end_token[matched])) {
      ++matched;
      if (matched == end_token.size() && (peek() < 0 || is_space(peek()))) return;
    } else {
      matched = 0;
    }
    line_start = c == '\n';
  }
}

long TokenReader::count(const std::string& what, std::uint64_t bytes_each, double limit) {
  const long n = integer();
  if (n < 0) fail("negative number of " + what + " (" + std::to_string(n) + ")");
  return checked_count(static_cast<std::uint64_t>(n), what, bytes_each, limit);
}

long TokenReader::checked_count(std::uint64_t n, const std::string& what, std::uint64_t bytes_each,
                                double limit) {
  if (static_cast<double>(n) > limit) {
    std::ostringstream message;
    message << n << " " << what << ": more than the " << limit << " a mesh may have";
    fail(message.str());
  }
  if (n > bytes_left() / bytes_each)
    fail(std::to_string(n) + " " + what + " announced, but the " + std::to_string(bytes_left()) +
         " bytes left in the file hold at most " + std::to_string(bytes_left() / bytes_each) +
         " (a damaged or truncated file)");
  return static_cast<long>(n);
}

void TokenReader::end_of_line() {
  while (peek() == ' ' || peek() == '\t' || peek() == '\r')
    get();
  if (get() != '\n') fail("expected the end of the line before binary data");
}

void TokenReader::bytes(void* data, std::size_t size, const char* what) {
  if (size > bytes_left())
    fail(std::string("the file ends inside the binary ") + what + " (byte " +
         std::to_string(offset_) + ")");
  // Copied as they are: a 0x0a byte of a number is not a line end.
  auto* out = static_cast<char*>(data);
  while (size > 0 && fill()) {
    const std::size_t n = std::min(size, end_ - begin_);
    std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(begin_),
              buffer_.begin() + static_cast<std::ptrdiff_t>(begin_ + n), out);
    begin_ += n;
    offset_ += n;
    out += n;
    size -= n;
  }
}

void TokenReader::fail(const std::string& what) const {
  throw InputError(file_, line_, "", what);
}

} // namespace sig
