// compile: builds a list of permutations in-process and in parallel (docs/targets.md).
// emit -> glslang -> spirv-val -> spirv-opt -> SPIRV-Cross targets -> checks, through the
// on-disk cache; identical emitted GLSL is compiled once. Results come back in input order
// and are bit-identical at every job count.
#pragma once
#include <string>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "compile/shader_cache.hpp"
#include "emit/emitter.hpp"
#include "library/shader_library.hpp"
#include "permute/permutation.hpp"

namespace mb {

struct BuildOptions {
  unsigned jobs = 0;                          // 0: std::thread::hardware_concurrency()
  std::vector<std::string> targets{"spirv"};  // subset of allTargets(); spirv always built
  std::filesystem::path cacheDir;             // empty: no cache
  EmitMode mode = EmitMode::Engine;           // what the package ships (emit/emitter.hpp)
  // Same outputs either way (glsl_compiler.hpp); Legacy only for the benchmark's comparison.
  CompilePipeline pipeline = CompilePipeline::Lean;
};

struct BuiltPermutation {
  EmittedShader shader;  // key, GLSL, layout, bricks
  CompiledArtifacts artifacts;
  std::string spirvHash;  // contentHash() of the SPIR-V words (16 hex digits)
  bool fromCache = false;
  double compileMs = 0;  // 0 for a cache hit, and for a permutation whose GLSL an
                         // earlier one already emitted (compiled once, reported once)
};

struct BuildStats {
  size_t permutations = 0;
  size_t compiled = 0;  // glslang actually ran (misses, after GLSL dedup)
  size_t cacheHits = 0;
  size_t cacheCorrupt = 0;  // entries found corrupt and rebuilt
  size_t uniqueSpirv = 0;   // distinct SPIR-V hashes
  double wallMs = 0;
};

// The cache key of one emitted shader (shader_cache.hpp): format version, MB_VERSION, the
// glslang/SPIRV-Tools/SPIRV-Cross versions, optimize/validate, the non-spirv targets with
// their options (targets.hpp targetOptions), the GLSL, and each included brick's file hash.
std::string buildCacheKey(const ShaderLibrary& lib, const EmittedShader& shader, bool optimize,
                          const std::vector<std::string>& targets);

// Throws DiagnosticError collecting every permutation's errors (GLSL errors at the user's
// file:line:column, E-TARGET-FAILED, ...); nothing is returned partially.
std::vector<BuiltPermutation> buildPermutations(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                                const BuildOptions& options, BuildStats* stats = nullptr);

}  // namespace mb
