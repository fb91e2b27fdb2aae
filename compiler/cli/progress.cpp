#include "cli/progress.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace mb::cli {
namespace {

constexpr int kBarWidth = 24;
// Line mode: a line per tenth of the work, or after this long without one ...
constexpr double kLineEverySeconds = 5.0;
// ... and never two within this (a fast command prints its last line only).
constexpr double kMinLineGapSeconds = 1.0;
// Terminal mode: redraws at most this often.
constexpr double kRedrawSeconds = 0.1;

double seconds(Progress::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

Progress::Progress(std::string label, size_t total, bool quiet, bool documentOnStdout)
    : Progress(std::move(label), total, std::cerr, isatty(STDERR_FILENO) == 1) {
  quiet_ = quiet || (documentOnStdout && !terminal_);
}

Progress::Progress(std::string label, size_t total, std::ostream& out, bool terminal,
                   std::function<Clock::time_point()> now)
    : label_(std::move(label)), out_(&out), terminal_(terminal), now_(std::move(now)), total_(total) {
  start_ = lastPrint_ = now_();
}

Progress::~Progress() { finish(); }

std::string Progress::formatDuration(double s) {
  const long total = s < 0 ? 0 : static_cast<long>(s + 0.5);
  char buf[32];
  if (total >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", total / 60, total % 60);
  return buf;
}

void Progress::advance(size_t n) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  done_ += n;
  if (done_ > total_) total_ = done_;
  if (quiet_ || done_ == total_) return;  // the total is finish()'s line
  const Clock::time_point t = now_();
  const double sinceLast = seconds(t - lastPrint_);
  const size_t tenth = total_ ? done_ * 10 / total_ : 0;
  if (terminal_ ? sinceLast >= kRedrawSeconds
                : sinceLast >= kMinLineGapSeconds && (tenth > lastTenth_ || sinceLast >= kLineEverySeconds)) {
    lastTenth_ = tenth;
    lastPrint_ = t;
    print(false);
  }
}

void Progress::addToTotal(size_t n) {
  std::lock_guard<std::mutex> lock(mutex_);
  total_ += n;
}

void Progress::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (!quiet_) print(true);
}

void Progress::print(bool last) {
  const double elapsed = seconds(now_() - start_);
  const double fraction = total_ ? static_cast<double>(done_) / total_ : 1.0;
  const int percent = static_cast<int>(fraction * 100);
  std::ostringstream line;
  if (terminal_) {
    const int filled = static_cast<int>(fraction * kBarWidth);
    // \r and "erase to end of line" (ECMA-48 EL): the line is redrawn in place.
    line << "\r" << label_ << " [" << std::string(filled, '#') << std::string(kBarWidth - filled, '.') << "] " << done_
         << "/" << total_ << "  " << percent << "%  ";
    if (last)
      line << formatDuration(elapsed) << "\x1b[K\n";
    else
      line << "ETA " << (done_ ? formatDuration(elapsed / done_ * (total_ - done_)) : "?") << "\x1b[K";
  } else {
    line << label_ << ": " << done_ << "/" << total_ << " (" << percent << "%)";
    if (last) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.1f", elapsed);
      line << " in " << buf << " s\n";
    } else {
      line << ", ETA " << (done_ ? formatDuration(elapsed / done_ * (total_ - done_)) : "?") << "\n";
    }
  }
  *out_ << line.str() << std::flush;
}

}  // namespace mb::cli
