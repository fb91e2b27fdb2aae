// compile: cross-compilation of a permutation's SPIR-V to the other targets with SPIRV-Cross's
// C API, each output checked before it is kept (targets.hpp, docs/targets.md).
#include "compile/targets.hpp"

#include <algorithm>

#include "compile/spvc_module.hpp"
#include "compile/target_checks.hpp"
#include "core/diagnostics.hpp"

namespace mb {
namespace {

// The msl row of core/target.cpp gives MSL 2.3 in SPIRV-Cross's encoding.
static_assert(SPVC_MAKE_MSL_VERSION(2, 3, 0) == 20300);

[[noreturn]] void fail(const std::string& displayName, Target target, const std::string& why) {
  throw DiagnosticError(
      {{Severity::Error, "E-TARGET-FAILED", {displayName, 0, 0}, "target " + targetName(target) + ": " + why}});
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

spvc_backend backendOf(TargetLanguage language) {
  switch (language) {
    case TargetLanguage::Glsl:
      return SPVC_BACKEND_GLSL;
    case TargetLanguage::Hlsl:
      return SPVC_BACKEND_HLSL;
    case TargetLanguage::Msl:
      return SPVC_BACKEND_MSL;
    case TargetLanguage::Spirv:
      break;
  }
  return SPVC_BACKEND_NONE;
}

// The language's options from the target's row: version, dialect, bindings.
void setOptions(const SpvcModule& m, spvc_compiler_options o, const TargetInfo& info) {
  switch (info.language) {
    case TargetLanguage::Glsl:
      spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_GLSL_VERSION, info.version);
      spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_ES, info.es);
      // Plain GLSL for OpenGL / GLES drivers: the Vulkan dialect is what the .spv already is.
      spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_VULKAN_SEMANTICS, false);
      spvc_compiler_options_set_bool(o, SPVC_COMPILER_OPTION_GLSL_EMIT_PUSH_CONSTANT_AS_UNIFORM_BUFFER, true);
      bindPushConstantsAsUniformBlock(m);
      return;
    case TargetLanguage::Hlsl:
      // Shader model 6.0 for fp16 too: fp16 values become min16float (HLSL's relaxed precision),
      // because glslang's HLSL front end cannot reparse SM 6.2's 16-bit output (templated
      // Load<T>, implicit float -> float16_t conversions), so it could not be checked.
      spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_HLSL_SHADER_MODEL, info.version);
      return;
    case TargetLanguage::Msl:
      spvc_compiler_options_set_uint(o, SPVC_COMPILER_OPTION_MSL_VERSION, info.version);
      return;
    case TargetLanguage::Spirv:
      return;
  }
}

// The language's checker (target_checks.hpp): "" when the output passes.
std::string check(const std::string& source, const SpvcModule& m, const TargetInfo& info) {
  const SpvExecutionModel model = spvc_compiler_get_execution_model(m.compiler());
  const bool fragment = model == SpvExecutionModelFragment;
  const ShaderStage stage = fragment                           ? ShaderStage::Fragment
                            : model == SpvExecutionModelVertex ? ShaderStage::Vertex
                                                               : ShaderStage::Compute;
  switch (info.language) {
    case TargetLanguage::Glsl:
      return info.compute ? checkGlsl(source, info.es, stage) : checkWebgl2(source, stage);
    case TargetLanguage::Hlsl:
      return checkHlsl(source, fragment);
    case TargetLanguage::Msl:
      return checkMsl(source, m);
    case TargetLanguage::Spirv:
      break;
  }
  return "not a cross-compilation target";
}

}  // namespace

std::string targetExtension(Target target) { return targetInfo(target).kernelExtension; }

std::string fragmentExtension(Target target) { return targetInfo(target).fragmentExtension; }

std::string crossCompile(const std::vector<uint32_t>& spirv, Target target, const std::string& displayName) {
  const TargetInfo& info = targetInfo(target);
  if (info.language == TargetLanguage::Spirv) fail(displayName, target, "not a cross-compilation target");
  // ES 3.10 has no 16-bit float type at all: SPIRV-Cross needs GL_AMD_gpu_shader_half_float or
  // GL_NV_gpu_shader5 for one, both desktop-only, and would emit '#error No extension available
  // for FP16'. Refuse here with the reason rather than ship that.
  // buildPermutations gives essl310 the permutation's mediump form instead (docs/targets.md).
  if (!info.float16 && usesFloat16(spirv))
    fail(displayName, target,
         "ESSL 3.10 has no 16-bit float type (SPIRV-Cross needs GL_AMD_gpu_shader_half_float or "
         "GL_NV_gpu_shader5, which ES lacks): cross-compile the permutation's mediump form "
         "(emitPermutation with mediump), whose floats ES drivers run at 16 bits");
  SpvcModule m(spirv, backendOf(info.language));
  if (!m.ok()) fail(displayName, target, "SPIRV-Cross: " + m.error());
  spvc_compiler c = m.compiler();
  spvc_compiler_options o = nullptr;
  spvc_compiler_create_compiler_options(c, &o);
  setOptions(m, o, info);
  spvc_compiler_install_compiler_options(c, o);
  const char* out = nullptr;
  if (spvc_compiler_compile(c, &out) != SPVC_SUCCESS || !out) fail(displayName, target, "SPIRV-Cross: " + m.error());
  std::string source = out;
  if (const std::string problem = check(source, m, info); !problem.empty()) fail(displayName, target, problem);
  return source;
}

std::string targetOptions(Target target) {
  const TargetInfo& info = targetInfo(target);
  const std::string version = std::to_string(info.version);
  switch (info.language) {
    case TargetLanguage::Glsl:
      return (info.es ? "essl " : "glsl ") + version + info.optionFlags;
    case TargetLanguage::Hlsl:
      return "hlsl sm" + version + info.optionFlags;
    case TargetLanguage::Msl:
      return "msl " + version + info.optionFlags;
    case TargetLanguage::Spirv:
      break;
  }
  return targetName(target);
}

std::string spirvCrossVersion() {
  unsigned major = 0, minor = 0, patch = 0;
  spvc_get_version(&major, &minor, &patch);
  const char* rev = spvc_get_commit_revision_and_timestamp();
  return "SPIRV-Cross C API " + std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch) +
         (rev && *rev ? std::string(" ") + rev : "");
}

}  // namespace mb
