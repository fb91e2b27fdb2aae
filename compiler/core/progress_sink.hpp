// core: where long-running library code (energy, bench, lut) reports units of work done, so
// that the CLI can show progress (cli/progress.hpp implements it) without the library knowing
// about terminals. Implementations are thread-safe.
#pragma once
#include <cstddef>

namespace mb {

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // More units than announced so far.
  virtual void addToTotal(size_t n) = 0;
  // `n` units done.
  virtual void advance(size_t n = 1) = 0;
};

}  // namespace mb
