// Shared by the tests that run the CLI on files: a fresh temporary directory per test
// process, and the path of a shipped example material.
#pragma once
#include <filesystem>
#include <string>
#include <unistd.h>

#include "support/pipeline_support.hpp"

namespace mb::test {

// <tmp>/mb_<prefix>_<name>_<pid>, empty.
inline std::filesystem::path freshTempDir(const std::string& prefix, const std::string& name) {
  std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("mb_" + prefix + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

inline std::string materialPath(const std::string& file) { return (sourceDir() / "materials" / file).string(); }

}  // namespace mb::test
