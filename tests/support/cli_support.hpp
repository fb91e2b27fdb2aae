// Shared by the tests that run the CLI on files: a fresh temporary directory per test
// process, the path of a shipped example material, and a package compiled and read back.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

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

struct CompiledPackage {
  nlohmann::json manifest;
  std::map<std::string, std::string> files;  // relative path -> bytes
};

// `matbricks compile -q ARGS -o OUT`, which must succeed, and every file it wrote.
inline CompiledPackage compilePackage(const std::string& args, const std::filesystem::path& out) {
  auto r = runCli("compile -q " + args + " -o " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CompiledPackage p;
  p.manifest = nlohmann::json::parse(readFile(out / "manifest.json"));
  for (const auto& e : std::filesystem::recursive_directory_iterator(out))
    if (e.is_regular_file()) p.files[std::filesystem::relative(e.path(), out).generic_string()] = readFile(e.path());
  return p;
}

}  // namespace mb::test
