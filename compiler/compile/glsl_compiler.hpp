// In-process GLSL -> SPIR-V -> spirv-val -> spirv-opt, with the glslang and SPIRV-Tools
// C++ APIs (never a glslangValidator process per permutation).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/optimization_level.hpp"

namespace mb {

// How spirv-val and spirv-opt are driven. Both give the same SPIR-V (the same passes in the
// same order) and accept and reject the same modules; they differ in cost only
// (docs/performance-compile.md).
enum class CompilePipeline {
  // spirv-val with friendly names off (naming every id costs most of its time; a rejected
  // module is validated again with them on, so its message still names types and variables),
  // and spirv-opt told not to validate its input again, which spirv-val just did.
  Lean,
  // Before issue 15: friendly names on, and spirv-opt re-validating its input, so a module
  // was validated three times. Kept so that mb_bench_compile measures both in one run.
  Legacy,
};

// The pipeline stage of the GLSL: the package's kernel and the probes are compute shaders; each
// permutation also has a fragment shader (docs/fragment-stage.md).
// Vertex: the fragment stage's reference vertex shader, which the preview draws with.
enum class ShaderStage { Compute, Fragment, Vertex };

// The spirv-opt flags of O1, as `spirv-opt` takes them.
const std::vector<std::string>& o1PassFlags();
// The level as a cache key part: O2 and O0 keep the words the keys had before levels existed
// ("optimize", "no-optimize"), so existing cache entries stay valid; O1 names its passes, so
// that changing them changes the key.
std::string optimizationCacheToken(OptimizationLevel level);

struct CompileOptions {
  ShaderStage stage = ShaderStage::Compute;
  OptimizationLevel optimization = OptimizationLevel::O2;
  bool validate = true;  // spirv-val before and after optimization
  CompilePipeline pipeline = CompilePipeline::Lean;
};

// Where one compile's time went, in ms (the breakdown of docs/performance-compile.md).
struct CompileStageTimes {
  double parseMs = 0;              // glslang TShader::parse (preprocess, parse, semantic checks)
  double linkMs = 0;               // glslang TProgram::link
  double codegenMs = 0;            // glslang GlslangToSpv
  double validateMs = 0;           // spirv-val of glslang's SPIR-V
  double optimizeMs = 0;           // spirv-opt (Legacy: including its own validation of the input)
  double validateOptimizedMs = 0;  // spirv-val of spirv-opt's SPIR-V
};

struct CompileResult {
  std::vector<uint32_t> spirv;
  double frontEndMs = 0;  // glslang parse + link + GlslangToSpv
  double optimizeMs = 0;  // spirv-val + spirv-opt + spirv-val
  CompileStageTimes stages;
};

// Compiles a GLSL 450 shader of options.stage (a compute shader by default). `displayName` names the generated file in errors that
// are not covered by a #line directive. GLSL errors become DiagnosticError entries with the
// file and line that the #line directives point at (a brick's file, the user's file).
CompileResult compileComputeGlsl(const std::string& source, const std::string& displayName,
                                 const CompileOptions& options = {});

// spirv-val of a module under `env` (a spv_target_env), as compileComputeGlsl runs it with
// Vulkan 1.1 rules: "" when valid, else the validator's messages. Lean validates with friendly
// names off and, only for a rejected module, again with them on, so the messages are the
// Legacy ones ("[word N] message; " each, or the first only with `firstOnly`).
std::string spirvValidationErrors(const std::vector<uint32_t>& spirv, int env,
                                  CompilePipeline pipeline = CompilePipeline::Lean, bool firstOnly = false);

// Initializes glslang once per process; thread-safe. Every glslang user calls it first.
void ensureGlslangInitialized();

// glslang + SPIRV-Tools versions, for cache keys and --version.
std::string toolchainVersion();
// Number of instructions in a SPIR-V module (deterministic cost proxy).
size_t spirvInstructionCount(const std::vector<uint32_t>& spirv);

}  // namespace mb
