#pragma once
// A mesh file read as it streams by, never held whole: whitespace-separated tokens with their
// line number, so that every reader error can say "file:line: ..." (sig::InputError), and the raw
// bytes of binary sections (gmsh binary .msh). The bytes left in the file are always known, so a
// count read from a header is checked against what the file can hold before anything is
// allocated for it. Private to the mesh readers.
#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sig {

class TokenReader {
public:
  /// Open the file; throws sig::Error naming it if it cannot be read.
  explicit TokenReader(const std::filesystem::path& path);
  /// Read `contents` as if it were the file `name` (tests, fuzzing).
  TokenReader(std::string name, std::string contents);

  const std::string& file() const { return file_; }
  bool at_end();                     ///< no token left
  int line() const { return line_; } ///< line of the token read last (1-based)
  std::uint64_t bytes_left() const { return size_ - offset_; }

  std::string_view word(); ///< next token; "unexpected end of file" at the end
  long integer();          ///< next token as an integer
  double real();           ///< next token as a finite real
  void expect(std::string_view token);
  /// Skip everything up to and including the line `end_token` (an unknown $Section ...
  /// $EndSection, text or binary).
  void skip_past(std::string_view end_token);

  /// A count from the file, >= 0, of items taking at least `bytes_each` bytes each in it:
  /// refused (naming `what`) when the rest of the file cannot hold that many, or when it is more
  /// than `limit`, before anything is allocated for them.
  long count(const std::string& what, std::uint64_t bytes_each, double limit = 1e8);
  /// The same check for a count read otherwise (a binary word).
  long checked_count(std::uint64_t n, const std::string& what, std::uint64_t bytes_each,
                     double limit = 1e8);

  /// Binary sections: the end of the current line, then raw little-endian values.
  void end_of_line();
  void bytes(void* data, std::size_t size, const char* what);
  template <class T> T binary(const char* what) {
    T value;
    bytes(&value, sizeof value, what);
    return value;
  }

  /// Throw InputError(file, line of the last token, "", what).
  [[noreturn]] void fail(const std::string& what) const;

private:
  int get(); ///< next byte or -1, counting lines
  int peek();
  bool fill();

  std::string file_;
  std::unique_ptr<std::istream> in_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0; ///< unread bytes of buffer_
  std::uint64_t size_ = 0, offset_ = 0;
  std::string token_;
  int line_ = 1;      ///< line of the last token returned
  int scan_line_ = 1; ///< line at offset_
};

} // namespace sig
