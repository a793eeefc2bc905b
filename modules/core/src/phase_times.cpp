#include "core/phase_times.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace sig {

namespace {
struct Phase {
  const char* name;
  double seconds = 0;
  int running = 0;
};

using Clock = std::chrono::steady_clock;

// Set during static initialisation: close enough to the process's start (the loader's and
// the shared libraries' time before it is not a stage's).
const Clock::time_point process_start = Clock::now();

double now() {
  return std::chrono::duration<double>(Clock::now() - process_start).count();
}

std::vector<Phase>& phases() {
  static std::vector<Phase> table;
  return table;
}

Phase& phase_named(const char* name) {
  auto& table = phases();
  auto it = std::find_if(table.begin(), table.end(),
                         [&](const Phase& p) { return std::strcmp(p.name, name) == 0; });
  if (it != table.end()) return *it;
  table.push_back({name});
  return table.back();
}
} // namespace

PhaseTimer::PhaseTimer(const char* phase) : phase_(phase), outermost_(false), start_(0) {
  Phase& p = phase_named(phase_);
  outermost_ = p.running++ == 0;
  if (outermost_) start_ = now();
}

PhaseTimer::~PhaseTimer() {
  Phase& p = phase_named(phase_);
  --p.running;
  if (outermost_) p.seconds += now() - start_;
}

std::vector<std::pair<std::string, double>> phase_times() {
  std::vector<std::pair<std::string, double>> times;
  for (const Phase& p : phases())
    times.emplace_back(p.name, p.seconds);
  return times;
}

void forget_phase_times() {
  std::erase_if(phases(), [](const Phase& p) { return p.running == 0; });
}

double process_seconds() {
  return now();
}

void append_phase_times(const std::string& program) {
  const char* file = std::getenv("SIG_PHASE_TIMES");
  if (file == nullptr || *file == '\0') return;
  std::FILE* out = std::fopen(file, "a");
  if (out == nullptr) return; // a benchmark's record: never a reason for a stage to fail
  for (const auto& [phase, seconds] : phase_times())
    std::fprintf(out, "%s\t%s\t%.6f\n", program.c_str(), phase.c_str(), seconds);
  std::fprintf(out, "%s\ttotal\t%.6f\n", program.c_str(), process_seconds());
  std::fclose(out);
}

} // namespace sig
