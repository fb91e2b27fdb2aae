// What `compile` and `merge` share: the compile command's arguments and the run's printing.
// The run itself is the driver's (driver/compile_run.hpp); `merge` rebuilds the request from
// the shards' shard.json (driver/compile_request.hpp) and runs the same compile with every unit
// taken from the shards, so its package is byte-identical to the one a single `compile` writes
// (docs/targets.md "Shards").
#pragma once
#include <vector>

#include "cli/cli_common.hpp"
#include "compile/shard.hpp"
#include "driver/compile_request.hpp"

namespace mb::cli {

struct CompileArgs {
  CompileRequest request;  // the global --shaderlib is filled in when the command runs
  // --lights, --environment, --precision, --quality and --targets as named (IsMember checks
  // them), parsed into the request when the command runs.
  std::vector<std::string> lights{"dir"};
  std::string environment = "none";
  std::string precision = "fp32";
  std::string quality = "high";
  std::vector<std::string> targets;
  // --lights, --environment, --precision, --quality: set, they conflict with --scene.
  CLI::Option* axisOptions[4] = {};
};

// Runs the request (driver/compile_run.hpp) and prints what it built, the --explain counts and
// the summary line. `mergeFrom` set: the merge of those shards; `protectedInputs` are further
// paths the output may not touch (the shard directories).
int runCompile(const CompileArgs& a, const GlobalOptions& g, const ShardSet* mergeFrom = nullptr,
               const std::vector<ProtectedPath>& protectedInputs = {});

}  // namespace mb::cli
