#pragma once
// Two levels of checks (STYLE.md): SIG_VERIFY is always on and throws sig::Error with the
// streamed message; SIG_ASSERT guards internal invariants in debug builds only. Errors in user
// input are sig::InputError, which names the file, line and field so the user can fix the deck.
#include <sstream>
#include <stdexcept>
#include <string>

namespace sig {

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// An error in an input file: the message reads "file:line: field 'name': what".
/// line = 0 means the whole file (e.g. a missing card); an empty field means the whole line.
class InputError : public Error {
public:
  InputError(std::string file, int line, std::string field, const std::string& what);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

private:
  std::string file_;
  int line_;
  std::string field_;
};

/// A matrix a linear solver cannot factorize: singular, or not positive definite for an spd
/// factorization (solver/linear_solver.hpp). The message is the solver's; the stage says why in
/// the deck's words (explain_factorization_failures, core/stage.hpp).
class FactorizationFailure : public Error {
public:
  using Error::Error;
};

} // namespace sig

#define SIG_VERIFY(cond, msg)                                                                      \
  do {                                                                                             \
    if (!(cond)) {                                                                                 \
      std::ostringstream sig_verify_stream_;                                                       \
      sig_verify_stream_ << msg;                                                                   \
      throw ::sig::Error(sig_verify_stream_.str());                                                \
    }                                                                                              \
  } while (0)

#ifdef NDEBUG
#define SIG_ASSERT(cond, msg) ((void)0)
#else
#define SIG_ASSERT(cond, msg)                                                                      \
  do {                                                                                             \
    if (!(cond)) {                                                                                 \
      std::ostringstream sig_assert_stream_;                                                       \
      sig_assert_stream_ << __FILE__ << ":" << __LINE__                                            \
                         << ": assertion " #cond " failed: " << msg;                               \
      throw ::sig::Error(sig_assert_stream_.str());                                                \
    }                                                                                              \
  } while (0)
#endif
