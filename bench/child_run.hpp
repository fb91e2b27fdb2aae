// Runs a command as a child process and measures it: exit status, wall time and peak resident
// memory (ru_maxrss from wait4(2)). A forked child's ru_maxrss includes its parent's at the
// fork (Linux keeps the pre-exec high-water mark), so callers keep their own memory small.
#pragma once
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace mb::bench {

struct ChildRun {
  int status = -1;
  double wallS = 0;
  long peakRssKb = 0;
};

// `args[0]` is the program's path; its stdout goes to `log`, its stderr to `errLog` (kept
// when empty).
inline ChildRun runChild(const std::vector<std::string>& args, const std::filesystem::path& log,
                         const std::filesystem::path& errLog = {}) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!std::freopen(log.c_str(), "w", stdout)) _exit(126);
    if (!errLog.empty() && !std::freopen(errLog.c_str(), "w", stderr)) _exit(126);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  ChildRun r;
  rusage usage{};
  wait4(pid, &r.status, 0, &usage);
  r.wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.peakRssKb = usage.ru_maxrss;
  return r;
}

}  // namespace mb::bench
