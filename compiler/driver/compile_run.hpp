// The compile run (docs/cli.md `compile`, docs/targets.md "Shards"): a request's materials or
// scene -> the required permutations -> built in parallel through the caches, to every target
// -> a package, a shard or (merge) the package joined from shards, written atomically, and the
// depfile. `matbricks compile` and `merge` only parse their arguments into a CompileRequest and
// print what the hooks hand them; a test or a benchmark runs a request the same way.
#pragma once
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "compile/shard.hpp"
#include "core/diagnostics.hpp"
#include "driver/compile_request.hpp"
#include "write/output_paths.hpp"

namespace mb {

// A request the command line refuses as a usage error (exit 2): options that conflict, or one
// that is missing or malformed. Bad input files are DiagnosticError (exit 3), as everywhere.
struct CompileUsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the run hands its caller while it runs; any may be empty.
struct CompileHooks {
  // Warnings as they arise: the materials' or the scene's before anything is built, then the
  // caches'.
  std::function<void(const std::vector<Diagnostic>&)> warnings;
  // Each permutation of this shard (all of them, unsharded), in plan order, once it is built.
  std::function<void(const BuiltPermutation&)> built;
  // With `explain`: the counts (permute/scene_plan.hpp explainText), once everything is built
  // and before the package is written.
  std::function<void(const std::string&)> explain;
};

struct CompileOutcome {
  BuildStats stats;
  ShardSpec shard;      // the request's, parsed (whole by default)
  unsigned jobs = 0;    // the request's jobs (0: every core)
  bool remote = false;  // a remote cache stood behind the local one
};

// Throws CompileUsageError or DiagnosticError before anything is compiled or written when the
// request cannot run. `mergeFrom` set: the merge of those shards (compile/build.hpp
// BuildOptions::mergeFrom); `protectedInputs` are further paths the output may not touch (the
// shard directories).
CompileOutcome runCompile(const CompileRequest& request, const CompileHooks& hooks = {},
                          const ShardSet* mergeFrom = nullptr, const std::vector<ProtectedPath>& protectedInputs = {});

}  // namespace mb
