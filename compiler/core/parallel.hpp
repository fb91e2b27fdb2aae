// A minimal parallel loop for CPU-side measurements: ground-truth quadratures (the split-sum
// DFG integral costs ~1 ms a call) and LUT texels. References are pure functions
// (their only mutable state, the conditioning skew, is thread_local), so records can be
// evaluated concurrently; callers accumulate results in index order, keeping outputs
// independent of the thread count.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mb {

template <class Fn>
void parallelFor(size_t n, Fn fn) {
  const size_t threads = std::min<size_t>(std::max(1u, std::thread::hardware_concurrency()), n);
  std::atomic<size_t> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto work = [&] {
    try {
      for (size_t i; (i = next.fetch_add(1)) < n;) fn(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      next = n;
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace mb
