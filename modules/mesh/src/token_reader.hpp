#pragma once
// Whitespace-separated tokens of an ASCII mesh file, each with its line number, so that every
// reader error can say "file:line: ..." (sig::InputError). Private to the mesh readers.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sig {

class TokenReader {
public:
  /// Read the whole file; throws sig::Error naming the file if it cannot be read.
  explicit TokenReader(const std::filesystem::path& path);

  const std::string& file() const { return file_; }
  bool at_end();                     ///< no token left
  int line() const { return line_; } ///< line of the token read last (1-based)

  std::string_view word(); ///< next token; "unexpected end of file" at the end
  long integer();          ///< next token as an integer
  double real();           ///< next token as a real
  void expect(std::string_view token);
  /// Skip tokens up to and including `end_token` (an unknown $Section ... $EndSection).
  void skip_past(std::string_view end_token);

  /// Throw InputError(file, line of the last token, "", what).
  [[noreturn]] void fail(const std::string& what) const;

private:
  void skip_space();
  std::string file_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 1;      ///< line of the last token returned
  int scan_line_ = 1; ///< line at pos_
};

} // namespace sig
