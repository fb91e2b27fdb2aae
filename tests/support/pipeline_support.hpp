// Shared by tests that need the shipped library, example materials, or the CLI binary.
#pragma once
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>
#include <sys/wait.h>

#include "support/build_paths.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "load/scene_desc.hpp"

namespace mb::test {

inline std::filesystem::path sourceDir() { return buildSourceDir(); }

inline const ShaderLibrary& shippedLibrary() {
  static ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  return lib;
}

// materials/<name>.json, loaded against the shipped library.
inline MaterialDesc shippedMaterial(const std::string& name) {
  return loadMaterialJson((sourceDir() / "materials" / (name + ".json")).string(), shippedLibrary());
}

// A scene use that states these input values.
inline MaterialUse useWith(std::map<std::string, std::vector<double>> values) {
  MaterialUse u;
  u.values = std::move(values);
  return u;
}

inline std::vector<std::string> exampleMaterialFiles() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "materials"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

struct CliResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs the matbricks CLI (path from $MATBRICKS_CLI, set by CTest) with `args`, prefixed by
// optional environment assignments such as "VK_ICD_FILENAMES=/x", from `cwd` if given.
inline CliResult runCli(const std::string& args, const std::string& env = "", const std::string& cwd = "") {
  const char* cli = std::getenv("MATBRICKS_CLI");
  std::string cmd = (cwd.empty() ? "" : "cd '" + cwd + "' && ") + (env.empty() ? "" : "env " + env + " ") +
                    std::string(cli ? cli : "matbricks") + " " + args + " 2>&1";
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  int status = pclose(p);
  // A signal shows as 128 + its number, as a shell reports it (exit 139 = SIGSEGV).
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : (WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1);
  return r;
}

inline std::string readFile(const std::filesystem::path& p) {
  FILE* f = std::fopen(p.string().c_str(), "rb");
  std::string s;
  if (!f) return s;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) s.append(buf.data(), n);
  std::fclose(f);
  return s;
}

}  // namespace mb::test
