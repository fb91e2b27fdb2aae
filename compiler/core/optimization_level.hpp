// The optimization level of a compile, shared by the loaders (a scene's "optimization"), the
// command line and the compiler, which maps it to spirv-opt passes (compile/glsl_compiler.hpp).
#pragma once
#include <string>

namespace mb {

// How much spirv-opt does (`compile -O0|-O1|-O2`, docs/performance-compile.md "Levels"). The
// drivers compile SPIR-V again with their own optimizer, so a level trades compile time here
// against the driver's work and the kernel's run time there; the bench measures both.
//   O0  no spirv-opt: glslang's SPIR-V, validated. SPIRV-Cross takes it as it is.
//   O1  per-function clean-up without inlining: dead functions, local loads and stores to SSA,
//       dead code; the passes that cost little on glslang's output (mb_bench_compile "levels").
//   O2  SPIRV-Tools' performance recipe (RegisterPerformancePasses), the package default.
enum class OptimizationLevel { O0, O1, O2 };
// "O0", "O1", "O2".
const char* optimizationLevelName(OptimizationLevel level);
// Parses "0".."2" or "O0".."O2"; false for anything else.
bool parseOptimizationLevel(const std::string& text, OptimizationLevel& level);

}  // namespace mb
