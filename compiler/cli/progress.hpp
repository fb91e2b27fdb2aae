// cli: progress of a long command on stderr (docs/cli.md "Progress"). One object per phase of
// work counted in units (permutations, bricks, grid cells, texel rows):
//   stderr is a terminal   one line redrawn in place:
//                          "validate [########......] 12/30  40%  ETA 0:07"
//   stderr is not          plain lines, one per tenth of the work or every 5 s, whichever
//                          comes first, never more than one a second, and the last at the total:
//                          "validate: 12/30 (40%), ETA 0:07"  ...  "validate: 30/30 (100%) in 9.1 s"
//   quiet (-q)             nothing
//   a document on stdout   (--json) no plain lines off a terminal: a consumer that captures
//                          stderr with stdout (2>&1) still reads one JSON document; the bar
//                          on a terminal stays
// advance() is thread-safe (validate and bench work on several threads); output is written
// under a lock, each line whole. Output goes to stderr only, so the reports on stdout that
// scripts and tests parse never change.
//
// Commands use it as
//   Progress progress("validate", records.size(), a.quiet);
//   for (...) { work(); progress.advance(); }
//   progress.finish();  // or let the destructor do it
#pragma once
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>

#include "core/progress_sink.hpp"

namespace mb::cli {

class Progress : public ProgressSink {
 public:
  using Clock = std::chrono::steady_clock;

  // On std::cerr, as a bar when stderr is a terminal (isatty), else as lines; nothing at all
  // when `quiet`, and no lines when `documentOnStdout` (see above).
  Progress(std::string label, size_t total, bool quiet, bool documentOnStdout = false);
  // On `out`, as a bar when `terminal`; `now` replaces the clock (tests).
  Progress(std::string label, size_t total, std::ostream& out, bool terminal,
           std::function<Clock::time_point()> now = Clock::now);
  ~Progress() override;
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `n` more units done. Thread-safe; past the total it counts on, and the total grows with it.
  void advance(size_t n = 1) override;
  // More units than announced (work found on the way). Thread-safe.
  void addToTotal(size_t n) override;
  // The last line ("... in 9.1 s"), once; the bar's line is ended. Called by the destructor.
  void finish();

  // "0:07", "1:02:03": the ETA and duration format.
  static std::string formatDuration(double seconds);

 private:
  void print(bool last);  // under mutex_

  std::string label_;
  std::ostream* out_;
  bool terminal_ = false;
  bool quiet_ = false;
  std::function<Clock::time_point()> now_;
  std::mutex mutex_;
  size_t done_ = 0, total_ = 0;
  Clock::time_point start_, lastPrint_;
  size_t lastTenth_ = 0;
  bool finished_ = false;
};

}  // namespace mb::cli
