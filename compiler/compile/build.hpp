// compile: builds a list of permutations in-process and in parallel (docs/targets.md).
// emit -> glslang -> spirv-val -> spirv-opt -> SPIRV-Cross targets -> checks, through the
// on-disk cache; identical emitted GLSL is compiled once. Results come back in input order
// and are bit-identical at every job count.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "compile/remote_cache.hpp"
#include "compile/shader_cache.hpp"
#include "compile/shard.hpp"
#include "core/diagnostics.hpp"
#include "core/package_stages.hpp"
#include "core/target.hpp"
#include "emit/emitter.hpp"
#include "library/shader_library.hpp"
#include "permute/permutation.hpp"

namespace mb {

struct BuildOptions {
  unsigned jobs = 0;                           // 0: std::thread::hardware_concurrency()
  std::vector<Target> targets{Target::Spirv};  // spirv is always built
  std::filesystem::path cacheDir;              // empty: no cache
  EmitMode mode = EmitMode::Engine;            // what the package ships (emit/emitter.hpp)
  // Engine mode: which stages every compile unit builds, to the same targets and cached in
  // one entry: the kernel and the permutation's fragment shader (emit/fragment_shader.hpp).
  // Probe mode always builds the kernel alone (validate, stress and bench run kernels).
  PackageStages stages;
  // spirv-opt's level for fp32 units (glsl_compiler.hpp OptimizationLevel; fp16 kernels are
  // always O0, their essl310 mediump forms at this level). Part of every unit's cache key.
  OptimizationLevel optimization = OptimizationLevel::O2;
  // Same outputs either way (glsl_compiler.hpp); Legacy only for the benchmark's comparison.
  CompilePipeline pipeline = CompilePipeline::Lean;
  RemoteCache* remote = nullptr;  // behind the local cache (remote_cache.hpp); null: none
  ShardSpec shard;                // build only this shard's units (shard.hpp); whole by default
  // merge: every unit's artifacts come from these shards; nothing is compiled, no cache is
  // used, and a unit the shards lack is an error (E-SHARD-MISSING).
  const ShardSet* mergeFrom = nullptr;
  // buildPermutationsStreaming: permutations emitted and compiled per window of this many, so
  // that memory is bounded by the window, not the build; 0: one window. Output is the same at
  // every window size (a unit seen in an earlier window is not compiled again).
  size_t window = 0;
};

struct BuiltPermutation {
  EmittedShader shader;  // key, GLSL, layout, bricks
  CompiledArtifacts artifacts;
  // The kernel's: contentHash() of the SPIR-V words (16 hex digits); "" and 0 when the
  // build made no kernel (BuildOptions::stages).
  std::string spirvHash;
  size_t spirvInstructions = 0;
  // The fragment shader's, "" and 0 when none was built (its code: artifacts.fragment).
  std::string fragmentHash;
  size_t fragmentInstructions = 0;
  CacheIdentity unit;   // of its compile unit (unit.key: its cache key)
  bool inShard = true;  // false: another shard builds it (artifacts empty, nothing to write)
  bool fromCache = false;
  double compileMs = 0;  // 0 for a cache hit, and for a permutation whose GLSL an
                         // earlier one already emitted (compiled once, reported once)
};

struct BuildStats {
  size_t permutations = 0;
  size_t compiled = 0;  // glslang actually ran (misses, after GLSL dedup)
  size_t cacheHits = 0;
  size_t cacheCorrupt = 0;     // entries found corrupt and rebuilt
  size_t cacheMismatch = 0;    // intact entries of another unit at a unit's path (evicted, rebuilt)
  size_t cacheUnreadable = 0;  // entries that are no regular file or cannot be read (evicted, rebuilt)
  size_t uniqueSpirv = 0;      // distinct kernels' SPIR-V hashes (fragment shaders' without kernels)
  size_t units = 0;            // compile units (distinct emitted GLSL) of the whole build
  size_t shardUnits = 0;       // of them, built here (all but under --shard)
  size_t remoteHits = 0;       // units the remote cache supplied
  size_t remoteCorrupt = 0;    // remote blobs that failed their checks (ignored, rebuilt)
  size_t remoteMismatch = 0;   // remote blobs holding another unit's entry (ignored, rebuilt)
  size_t remoteVerified = 0;   // remote hits compiled again and found identical (--cache-verify)
  size_t remoteUploads = 0;
  std::string remoteWarning;  // why the remote cache went off or read-only ("" if it did not)
  // W-CACHE-REMOTE (remoteWarning), W-CACHE-REMOTE-MISMATCH, W-CACHE-MISMATCH and
  // W-CACHE-UNREADABLE: at most one of each per build, the first case named, credentials never.
  std::vector<Diagnostic> cacheWarnings;
  std::string planDigest;  // shard.hpp planDigest over the units, for --shard N (else N = 1)
  double wallMs = 0;
};

// The cache key of one emitted shader (shader_cache.hpp): format version, MB_VERSION, the
// glslang/SPIRV-Tools/SPIRV-Cross versions, the optimization level, validate, the non-spirv targets with
// their options (targets.hpp targetOptions), the GLSL, and each included brick's file hash.
std::string buildCacheKey(const ShaderLibrary& lib, const EmittedShader& shader, OptimizationLevel optimization,
                          const std::vector<Target>& targets);

// Called for every permutation in input order, after its window is built; it may move from
// `built`. A permutation whose unit an earlier window built carries that unit's hash,
// instruction count, reflection and target names, but no code (artifacts.spirv empty, target
// texts empty): its files were already handed over with the unit's first permutation.
using BuiltSink = std::function<void(size_t index, BuiltPermutation& built)>;

// The build, streamed window by window (options.window). Errors as buildPermutations; once
// there is one, the sink is not called again, and the whole list is thrown at the end.
void buildPermutationsStreaming(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                const BuildOptions& options, const BuiltSink& sink, BuildStats* stats = nullptr);

// Throws DiagnosticError collecting every permutation's errors (GLSL errors at the user's
// file:line:column, E-TARGET-FAILED, ...); nothing is returned partially.
std::vector<BuiltPermutation> buildPermutations(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                                const BuildOptions& options, BuildStats* stats = nullptr);

}  // namespace mb
