// INTERIM (replaced by the parallel, cached build): sequential, SPIR-V only.
#include "compile/build.hpp"

#include <chrono>
#include <set>

#include "compile/glsl_compiler.hpp"
#include "write/package_writer.hpp"

namespace mb {

std::vector<BuiltPermutation> buildPermutations(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                                const BuildOptions& options, BuildStats* stats) {
  auto t0 = std::chrono::steady_clock::now();
  std::vector<BuiltPermutation> out;
  std::vector<Diagnostic> errors;
  std::set<std::string> hashes;
  for (const auto& perm : perms) {
    BuiltPermutation b;
    b.shader = emitPermutation(lib, perm, false, options.mode);
    auto t1 = std::chrono::steady_clock::now();
    try {
      CompileOptions co;
      co.optimize = perm.precision == "fp32";
      b.artifacts.spirv = compileComputeGlsl(b.shader.glsl, b.shader.fileName, co).spirv;
    } catch (const DiagnosticError& e) {
      errors.insert(errors.end(), e.diagnostics().begin(), e.diagnostics().end());
      continue;
    }
    b.compileMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    b.spirvHash = contentHash(b.artifacts.spirv.data(), b.artifacts.spirv.size() * 4);
    hashes.insert(b.spirvHash);
    out.push_back(std::move(b));
  }
  if (!errors.empty()) throw DiagnosticError(errors);
  if (stats) {
    stats->permutations = perms.size();
    stats->compiled = out.size();
    stats->uniqueSpirv = hashes.size();
    stats->wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  return out;
}

}  // namespace mb
