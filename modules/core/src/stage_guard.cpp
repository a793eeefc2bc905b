#include "core/stage_guard.hpp"

#include "core/error.hpp"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>
#include <system_error>
#include <thread>

namespace sig {

namespace {

struct Work {
  std::filesystem::path temporary;
  int child = 0;
};

struct Guard {
  std::mutex mutex;
  std::map<std::size_t, Work> unfinished;
  std::size_t next = 0;
  std::string program; ///< the stage whose body runs, empty outside one
  std::condition_variable wake;
  bool stop = false;
  std::thread watchdog;
};

// Never destroyed: the exit handler and the watchdog use it while the process ends.
Guard& guard() {
  static Guard* state = new Guard;
  return *state;
}

std::size_t add(Work work) {
  Guard& g = guard();
  const std::lock_guard lock(g.mutex);
  g.unfinished.emplace(g.next, std::move(work));
  return g.next++;
}

// With the mutex held: kill the children, remove the temporaries.
void undo_unfinished(Guard& g) {
  for (const auto& [id, work] : g.unfinished) {
    if (work.child > 0) {
      ::kill(-work.child, SIGKILL); // its process group: gmsh and what it started
      ::kill(work.child, SIGKILL);
    }
    std::error_code ignored;
    if (!work.temporary.empty()) std::filesystem::remove_all(work.temporary, ignored);
  }
  g.unfinished.clear();
}

// A library's exit() inside a stage's body (libgomp's "Thread creation failed"): the stage did
// not finish, whatever status the library gave.
void on_exit() {
  Guard& g = guard();
  const std::lock_guard lock(g.mutex);
  if (g.program.empty()) return;
  undo_unfinished(g);
  std::fprintf(stderr,
               "%s: error: a library ended the stage before it finished (its message is above): "
               "the system refused it a resource, memory or a thread (see ulimit -v, "
               "OMP_STACKSIZE, OMP_NUM_THREADS); its unfinished files were removed\n",
               g.program.c_str());
  std::fflush(stderr);
  std::_Exit(1);
}

} // namespace

Unfinished::Unfinished(const std::filesystem::path& temporary) : id_(add({temporary, 0})) {}

Unfinished::Unfinished(int child) : id_(add({{}, child})) {}

Unfinished::~Unfinished() {
  Guard& g = guard();
  const std::lock_guard lock(g.mutex);
  g.unfinished.erase(id_);
}

void start_time_limit(double seconds, const std::string& program) {
  Guard& g = guard();
  SIG_VERIFY(!g.watchdog.joinable(), program << ": the time limit is already running");
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(seconds));
  std::ostringstream message;
  message << program << ": error: the time limit of " << seconds
          << " s (--time-limit) ran out before " << program
          << " finished: stopped, with its unfinished files removed\n";
  try {
    g.watchdog = std::thread([&g, deadline, text = message.str()] {
      std::unique_lock lock(g.mutex);
      if (g.wake.wait_until(lock, deadline, [&g] { return g.stop; })) return;
      undo_unfinished(g);
      std::fputs(text.c_str(), stderr);
      std::fflush(stderr);
      std::_Exit(1);
    });
  } catch (const std::system_error& e) {
    SIG_VERIFY(false, program << ": cannot start the watchdog of --time-limit (" << e.what()
                              << "): the system refuses a thread");
  }
}

void enter_stage_body(const std::string& program) {
  static const bool registered = std::atexit(on_exit) == 0;
  SIG_VERIFY(registered, program << ": cannot register the exit handler");
  Guard& g = guard();
  const std::lock_guard lock(g.mutex);
  g.program = program;
}

void leave_stage_body() {
  Guard& g = guard();
  {
    const std::lock_guard lock(g.mutex);
    g.program.clear();
    g.stop = true;
  }
  g.wake.notify_all();
  if (g.watchdog.joinable()) g.watchdog.join();
  const std::lock_guard lock(g.mutex);
  g.stop = false;
}

} // namespace sig
