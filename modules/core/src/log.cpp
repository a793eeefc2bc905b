#include "core/log.hpp"

#include <cstdio>
#include <unistd.h>

namespace sig {

namespace {
// Off a terminal (a driver's log file) a line at most this often keeps logs short.
constexpr double quiet_interval_seconds = 5.0;

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// "label 120/2000 (6%) 1.2s, 100 steps/s, 18.8s left detail": the rate and the rest from the
// mean rate so far.
std::string progress_line(const std::string& label, const std::string& unit, long done, long total,
                          double elapsed, const std::string& detail) {
  char text[96];
  const double percent = total > 0 ? 100.0 * static_cast<double>(done) / total : 100.0;
  std::snprintf(text, sizeof text, " %ld/%ld (%.0f%%) %.1fs", done, total, percent, elapsed);
  std::string line = "[sig] " + label + text;
  if (done > 0 && elapsed > 0) {
    const double rate = static_cast<double>(done) / elapsed;
    std::snprintf(text, sizeof text, rate >= 100 ? ", %.0f " : ", %.3g ", rate);
    line += text + unit + "/s";
    if (done < total) {
      std::snprintf(text, sizeof text, ", %.1fs left", static_cast<double>(total - done) / rate);
      line += text;
    }
  }
  if (!detail.empty()) line += " " + detail;
  return line;
}
} // namespace

void log_info(const std::string& message) {
  std::fprintf(stderr, "[sig] %s\n", message.c_str());
}

void log_warning(const std::string& message) {
  std::fprintf(stderr, "[sig] warning: %s\n", message.c_str());
}

Progress::Progress(std::string label, long total, std::string unit)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total),
      tty_(::isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(long done, const std::string& detail) {
  const auto now = std::chrono::steady_clock::now();
  const std::string line =
      progress_line(label_, unit_, done, total_, seconds_between(start_, now), detail);
  if (tty_) {
    // \r and erase-to-end-of-line: one line rewritten in place.
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
  } else if (seconds_between(last_, now) >= quiet_interval_seconds) {
    std::fprintf(stderr, "%s\n", line.c_str());
    last_ = now;
  }
}

void Progress::finish(const std::string& detail) {
  const auto now = std::chrono::steady_clock::now();
  const std::string line =
      progress_line(label_, unit_, total_, total_, seconds_between(start_, now), detail);
  if (tty_)
    std::fprintf(stderr, "\r%s\033[K\n", line.c_str());
  else
    std::fprintf(stderr, "%s\n", line.c_str());
}

} // namespace sig
