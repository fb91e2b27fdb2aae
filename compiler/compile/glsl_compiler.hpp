// In-process GLSL -> SPIR-V -> spirv-val -> spirv-opt, with the glslang and SPIRV-Tools
// C++ APIs (never a glslangValidator process per permutation).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"

namespace mb {

struct CompileOptions {
  bool optimize = true;  // spirv-opt performance passes (RegisterPerformancePasses)
  bool validate = true;  // spirv-val before and after optimization
};

struct CompileResult {
  std::vector<uint32_t> spirv;
  double frontEndMs = 0;  // glslang parse + link + GlslangToSpv
  double optimizeMs = 0;  // spirv-val + spirv-opt + spirv-val
};

// Compiles a GLSL 450 compute shader. `displayName` names the generated file in errors that
// are not covered by a #line directive. GLSL errors become DiagnosticError entries with the
// file and line that the #line directives point at (a brick's file, the user's file).
CompileResult compileComputeGlsl(const std::string& source, const std::string& displayName,
                                 const CompileOptions& options = {});

// Initializes glslang once per process; thread-safe. Every glslang user calls it first.
void ensureGlslangInitialized();

// glslang + SPIRV-Tools versions, for cache keys and --version.
std::string toolchainVersion();
// Number of instructions in a SPIR-V module (deterministic cost proxy).
size_t spirvInstructionCount(const std::vector<uint32_t>& spirv);

}  // namespace mb
