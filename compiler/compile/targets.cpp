// compile: cross-compilation of a permutation's SPIR-V to the other targets with SPIRV-Cross's
// C API, each output checked before it is kept (targets.hpp, docs/targets.md).
#include "compile/targets.hpp"

#include <algorithm>

#include "compile/spvc_module.hpp"
#include "compile/target_checks.hpp"
#include "core/diagnostics.hpp"

namespace mb {
namespace {

constexpr unsigned kGlslVersion = 450, kEsslVersion = 310, kHlslShaderModel = 60;
constexpr unsigned kMslVersion = SPVC_MAKE_MSL_VERSION(2, 3, 0);

[[noreturn]] void fail(const std::string& displayName, const std::string& target, const std::string& why) {
  throw DiagnosticError({{Severity::Error, "E-TARGET-FAILED", {displayName, 0, 0}, "target " + target + ": " + why}});
}

// Whether the module does arithmetic in 16-bit floats (an fp16 permutation).
bool usesFloat16(const std::vector<uint32_t>& spirv) {
  constexpr uint32_t kOpCapability = 17, kCapabilityFloat16 = 9;
  for (size_t i = 5; i < spirv.size();) {
    const uint32_t words = spirv[i] >> 16, op = spirv[i] & 0xffff;
    if (words == 0) break;
    if (op == kOpCapability && words == 2 && spirv[i + 1] == kCapabilityFloat16) return true;
    i += words;
  }
  return false;
}

// OpenGL has no push constants: SPIRV-Cross turns the block into a std140 uniform block, and
// GL's uniform-block bindings are a namespace of their own, so it takes the first binding no
// uniform block of the module uses (docs/targets.md "GLSL 450 and ESSL 3.10").
void bindPushConstantsAsUniformBlock(const SpvcModule& m) {
  unsigned next = 0;
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER))
    next = std::max(next, spvc_compiler_get_decoration(m.compiler(), r.id, SpvDecorationBinding) + 1);
  for (const auto& r : m.resources(SPVC_RESOURCE_TYPE_PUSH_CONSTANT))
    spvc_compiler_set_decoration(m.compiler(), r.id, SpvDecorationBinding, next++);
}

spvc_backend backendOf(const std::string& target) {
  if (target == "glsl450" || target == "essl310") return SPVC_BACKEND_GLSL;
  if (target == "hlsl") return SPVC_BACKEND_HLSL;
  return SPVC_BACKEND_MSL;
}

}  // namespace

std::string targetExtension(const std::string& target) {
  if (target == "spirv") return ".spv";
  if (target == "glsl450") return ".comp";
  if (target == "essl310") return ".es.comp";
  if (target == "hlsl") return ".hlsl";
  return ".metal";
}

std::string fragmentExtension(const std::string& target) {
  if (target == "glsl450") return ".frag";
  if (target == "essl310") return ".es.frag";
  return targetExtension(target);
}

std::string crossCompile(const std::vector<uint32_t>& spirv, const std::string& target,
                         const std::string& displayName) {
  if (target == "spirv" || std::find(allTargets().begin(), allTargets().end(), target) == allTargets().end())
    fail(displayName, target, "not a cross-compilation target");
  const bool fp16 = usesFloat16(spirv);
  // ES 3.10 has no 16-bit float type at all: SPIRV-Cross needs GL_AMD_gpu_shader_half_float or
  // GL_NV_gpu_shader5 for one, both desktop-only, and would emit '#error No extension available
  // for FP16'. Refuse here with the reason rather than ship that.
  // buildPermutations gives essl310 the permutation's mediump form instead (docs/targets.md).
  if (fp16 && target == "essl310")
    fail(displayName, target,
         "ESSL 3.10 has no 16-bit float type (SPIRV-Cross needs GL_AMD_gpu_shader_half_float or "
         "GL_NV_gpu_shader5, which ES lacks): cross-compile the permutation's mediump form "
         "(emitPermutation with mediump), whose floats ES drivers run at 16 bits");
  SpvcModule m(spirv, backendOf(target));
  if (!m.ok()) fail(displayName, target, "SPIRV-Cross: " + m.error());
  spvc_compiler c = m.compiler();
  spvc_compiler_options o = nullptr;
  spvc_compiler_create_compiler_options(c, &o);
  if (target == "glsl450" || target == "essl310") {
    const bool es = target == "essl310";
    spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_GLSL_VERSION, es ? kEsslVersion : kGlslVersion);
    spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_ES, es);
    // Plain GLSL for OpenGL / GLES drivers: the Vulkan dialect is what the .spv already is.
    spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_VULKAN_SEMANTICS, false);
    spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_EMIT_PUSH_CONSTANT_AS_UNIFORM_BUFFER, true);
    bindPushConstantsAsUniformBlock(m);
  } else if (target == "hlsl") {
    // Shader model 6.0 for fp16 too: fp16 values become min16float (HLSL's relaxed precision),
    // because glslang's HLSL front end cannot reparse SM 6.2's 16-bit output (templated
    // Load<T>, implicit float -> float16_t conversions), so it could not be checked.
    spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_HLSL_SHADER_MODEL, kHlslShaderModel);
  } else {
    spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_MSL_VERSION, kMslVersion);
  }
  spvc_compiler_install_compiler_options(c, o);
  const char* out = nullptr;
  if (spvc_compiler_compile(c, &out) != SPVC_SUCCESS || !out) fail(displayName, target, "SPIRV-Cross: " + m.error());
  std::string source = out;
  std::string problem;
  const bool fragment = spvc_compiler_get_execution_model(c) == SpvExecutionModelFragment;
  if (target == "glsl450" || target == "essl310")
    problem = checkGlsl(source, target == "essl310", fragment);
  else if (target == "hlsl")
    problem = checkHlsl(source, fragment);
  else
    problem = checkMsl(source, m);
  if (!problem.empty()) fail(displayName, target, problem);
  return source;
}

std::string targetOptions(const std::string& target) {
  if (target == "glsl450") return "glsl " + std::to_string(kGlslVersion) + " non-vulkan push-as-ubo";
  if (target == "essl310") return "essl " + std::to_string(kEsslVersion) + " non-vulkan push-as-ubo fp16-as-mediump";
  if (target == "hlsl") return "hlsl sm" + std::to_string(kHlslShaderModel) + " min16float";
  if (target == "msl") return "msl " + std::to_string(kMslVersion) + " macos";
  return target;
}

std::string spirvCrossVersion() {
  unsigned major = 0, minor = 0, patch = 0;
  spvc_get_version(&major, &minor, &patch);
  const char* rev = spvc_get_commit_revision_and_timestamp();
  return "SPIRV-Cross C API " + std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch) +
         (rev && *rev ? std::string(" ") + rev : "");
}

}  // namespace mb
