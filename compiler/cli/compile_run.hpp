// What `compile` and `merge` share: the compile command's arguments and its run. `merge`
// rebuilds the arguments from the shards' shard.json (the "command" object below) and runs
// the same compile with every unit taken from the shards, so its package is byte-identical
// to the one a single `compile` writes (docs/targets.md "Shards").
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "compile/shard.hpp"

namespace mb::cli {

struct CompileArgs {
  std::vector<std::string> materials;
  std::string scene;
  std::string out;
  bool quiet = false;
  bool explain = false;
  std::vector<std::string> lights{"dir"};
  std::string environment = "none";
  std::string precision = "fp32";
  std::string quality = "high";
  std::vector<std::string> targets;  // empty: the scene's, else spirv
  std::string optimization;          // -O: "0".."2" or "O0".."O2"; empty: the scene's, else O2
  std::string stages;                // --stages: "kernel", "fragment" or both; empty: both
  unsigned jobs = 0;
  std::string cacheDir;
  bool noCache = false;
  std::string cacheUrl;  // empty: $MATBRICKS_CACHE_URL, else none
  std::string cacheUrlLayout = "subdirs";
  double cacheTimeout = 10;
  double cacheVerify = 0;  // fraction of remote hits compiled again and compared
  std::string shard;       // "i/N"; empty: the whole build
  // Permutations emitted and compiled per streamed window (docs/targets.md "Memory"): enough
  // units to keep every job busy between windows, few enough that a window's GLSL and
  // artifacts stay a few tens of MB. 0: the whole build at once.
  size_t streamWindow = 256;
  std::string headerName = "matbricks_materials.hpp";
  std::string cppNamespace = "matbricks_materials";
  std::string depfile;
  CLI::Option* axisOptions[4] = {};
};

// The inputs that decide a package's bytes (not -o, -j, caches or verbosity), as a shard
// records them, and back. `shaderlib` is the global --shaderlib.
nlohmann::json compileCommandJson(const CompileArgs& a, const GlobalOptions& g);
// Throws DiagnosticError (E-SHARD-NOT-SHARD at `file`) for a command object it cannot read.
void compileArgsFromJson(const nlohmann::json& command, const std::string& file, CompileArgs& a, GlobalOptions& g);

// `mergeFrom` set: the merge of those shards (compile/build.hpp BuildOptions::mergeFrom);
// `protectedInputs` are further paths the output may not touch (the shard directories).
int runCompile(const CompileArgs& a, const GlobalOptions& g, const ShardSet* mergeFrom = nullptr,
               const std::vector<ProtectedPath>& protectedInputs = {});

}  // namespace mb::cli
