#pragma once
// Logging to stderr, and a progress line for long loops (done/total, elapsed, rate per second,
// time left): on a terminal it rewrites one line, otherwise it prints at most every few seconds
// so logs stay short.
#include <chrono>
#include <string>

namespace sig {

void log_info(const std::string& message);
void log_warning(const std::string& message);

class Progress {
public:
  /// `unit`: what is counted, for the rate ("steps" -> "100 steps/s").
  Progress(std::string label, long total, std::string unit = "steps");
  /// Report step `done` of total with a short free text (time, energy ...).
  void update(long done, const std::string& detail = "");
  void finish(const std::string& detail = "");

private:
  std::string label_;
  std::string unit_;
  long total_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_;
};

/// Wall-clock seconds since construction.
class Stopwatch {
public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_;
};

} // namespace sig
