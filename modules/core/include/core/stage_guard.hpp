#pragma once
// What ends a stage from outside its own code: its wall-clock budget (--time-limit SECONDS) and a
// library that calls exit() (libgomp when the system refuses it a thread). Either way the stage's
// unfinished work is undone (the temporaries of its atomic writes and its scratch folders
// removed, its child processes killed: nothing partial is left) and the user reads why, as
// "sig-STAGE: error: ...", with exit status 1. run_stage and parse_stage_args (core/stage.hpp)
// set this up; the code that makes a temporary or starts a child registers it with Unfinished.
#include <cstddef>
#include <filesystem>
#include <string>

namespace sig {

/// While alive, `temporary` (a file or a folder) is removed, or the process group of `child`
/// killed, should the stage be ended from outside its code.
class Unfinished {
public:
  explicit Unfinished(const std::filesystem::path& temporary);
  explicit Unfinished(int child);
  ~Unfinished();
  Unfinished(const Unfinished&) = delete;
  Unfinished& operator=(const Unfinished&) = delete;

private:
  std::size_t id_;
};

/// The largest --time-limit: a day (longer runs are not a stage's).
inline constexpr double kMaxTimeLimit = 86400;

/// Start the wall-clock budget of the running stage: once `seconds` have passed, a watchdog
/// undoes the unfinished work, prints "PROGRAM: error: the time limit of SECONDS s
/// (--time-limit) ran out ..." and ends the process with status 1.
void start_time_limit(double seconds, const std::string& program);

/// run_stage's bracket around a stage's body: inside it, a library's exit() is reported as an
/// error of `program` with the unfinished work undone; leave_stage_body also stops the time limit.
void enter_stage_body(const std::string& program);
void leave_stage_body();

} // namespace sig
