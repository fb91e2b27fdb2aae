#include "compile/target_checks.hpp"

#include <cctype>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.h>

#include "compile/glsl_compiler.hpp"
#include "compile/hlsl_spirv.hpp"

namespace mb {
namespace {

// The first "ERROR: ..." line of a glslang info log (the rest repeats or summarizes it).
std::string firstError(const std::string& log) {
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("ERROR:", 0) == 0) return line;
  return log.empty() ? "glslang failed without a message" : log.substr(0, log.find('\n'));
}

std::string validate(const std::vector<uint32_t>& spirv, spv_target_env env) {
  const std::string first = spirvValidationErrors(spirv, env, CompilePipeline::Lean, true);
  return first.empty() ? "" : "spirv-val: " + first;
}

struct Reparse {
  glslang::EShSource source;
  glslang::EShClient client;
  glslang::EShTargetClientVersion clientVersion;
  glslang::EShTargetLanguageVersion spirvVersion;
  int defaultVersion;
  EShMessages messages;
  spv_target_env validateEnv;
  EShLanguage stage = EShLangCompute;
  unsigned samplerShift = 0;  // HLSL: s registers' binding offset (compileHlsl)
};

// `spirvOut`, when given, receives the generated module (valid when "" is returned).
std::string reparse(const std::string& text, const Reparse& r, std::vector<uint32_t>* spirvOut = nullptr) {
  ensureGlslangInitialized();
  glslang::TShader shader(r.stage);
  const char* str = text.c_str();
  shader.setStrings(&str, 1);
  shader.setEntryPoint("main");
  shader.setEnvInput(r.source, r.stage, r.client, 100);
  shader.setEnvClient(r.client, r.clientVersion);
  shader.setEnvTarget(glslang::EShTargetSpv, r.spirvVersion);
  if (r.samplerShift) shader.setShiftBinding(glslang::EResSampler, r.samplerShift);
  // The #version line of the source decides the profile; defaultVersion only applies without one.
  if (!shader.parse(GetDefaultResources(), r.defaultVersion, false, r.messages))
    return "glslang: " + firstError(shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(r.messages)) return "glslang link: " + firstError(program.getInfoLog());
  // The binding shifts take effect in the I/O mapping pass (as glslangValidator runs it).
  if (r.samplerShift && !program.mapIO()) return "glslang mapIO: " + firstError(program.getInfoLog());
  // Without the entry point glslang's HLSL front end only warns, and makes an empty main.
  if (std::string(program.getInfoLog()).find("Entry point not found") != std::string::npos)
    return "glslang link: no entry point 'main'";
  std::vector<uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.disableOptimizer = true;
  glslang::GlslangToSpv(*program.getIntermediate(r.stage), spirv, &logger, &options);
  std::string problem = validate(spirv, r.validateEnv);
  if (spirvOut) *spirvOut = std::move(spirv);
  return problem;
}

EShLanguage stageOf(bool fragment) { return fragment ? EShLangFragment : EShLangCompute; }

EShLanguage languageOf(ShaderStage stage) {
  return stage == ShaderStage::Vertex     ? EShLangVertex
         : stage == ShaderStage::Fragment ? EShLangFragment
                                          : EShLangCompute;
}

}  // namespace

std::string checkGlsl(const std::string& source, bool es, ShaderStage stage) {
  // The #version line decides how glslang parses: check that it is the target's.
  const std::string version = es ? "#version 310 es\n" : "#version 450\n";
  if (source.rfind(version, 0) != 0)
    return "expected the source to start with '" + version.substr(0, version.size() - 1) + "'";
  // Plain (non-Vulkan) GLSL: compiled as for OpenGL's ARB_gl_spirv, the closest glslang gets
  // to what a GL/GLES driver's compiler accepts.
  return reparse(source,
                 {glslang::EShSourceGlsl, glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450,
                  glslang::EShTargetSpv_1_0, es ? 310 : 450, EShMsgSpvRules, SPV_ENV_OPENGL_4_5, languageOf(stage)});
}

namespace {

// WebGL 2.0's reserved prefixes (target_checks.hpp checkWebgl2), over the source's words.
std::string webglIdentifierProblem(const std::string& source) {
  auto wordChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t i = 0; i < source.size();) {
    if (!wordChar(source[i])) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < source.size() && wordChar(source[end])) ++end;
    const std::string word = source.substr(i, end - i);
    if (word.rfind("webgl_", 0) == 0 || word.rfind("_webgl_", 0) == 0)
      return "WebGL 2.0: identifier '" + word + "' uses the reserved prefix webgl_ or _webgl_";
    i = end;
  }
  return "";
}

}  // namespace

std::string checkWebgl2(const std::string& source, ShaderStage stage) {
  const std::string version = "#version 300 es\n";
  if (source.rfind(version, 0) != 0) return "expected the source to start with '#version 300 es'";
  if (stage == ShaderStage::Compute) return "WebGL 2.0 has no compute shaders";
  ensureGlslangInitialized();
  const EShLanguage language = languageOf(stage);
  glslang::TShader shader(language);
  const char* str = source.c_str();
  shader.setStrings(&str, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  if (!shader.parse(GetDefaultResources(), 300, true, EShMsgDefault))
    return "glslang: " + firstError(shader.getInfoLog());
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(EShMsgDefault)) return "glslang link: " + firstError(program.getInfoLog());
  return webglIdentifierProblem(source);
}

namespace {

Reparse hlslReparse(bool fragment) {
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl);
  return {glslang::EShSourceHlsl,
          glslang::EShClientVulkan,
          glslang::EShTargetVulkan_1_1,
          glslang::EShTargetSpv_1_3,
          100,
          messages,
          SPV_ENV_VULKAN_1_1,
          stageOf(fragment)};
}

}  // namespace

std::string checkHlsl(const std::string& source, bool fragment) { return reparse(source, hlslReparse(fragment)); }

std::string compileHlsl(const std::string& source, std::vector<uint32_t>& spirv, bool fragment, unsigned samplerShift) {
  Reparse r = hlslReparse(fragment);
  r.samplerShift = samplerShift;
  return reparse(source, r, &spirv);
}

std::string checkMsl(const std::string& source, const SpvcModule& module) {
  spvc_compiler c = module.compiler();
  const bool fragment = spvc_compiler_get_execution_model(c) == SpvExecutionModelFragment;
  const char* entry = spvc_compiler_get_cleansed_entry_point_name(
      c, "main", fragment ? SpvExecutionModelFragment : SpvExecutionModelGLCompute);
  // A fragment function returns its outputs' struct: "fragment main0_out main0(".
  const std::string name = std::string(entry ? entry : "main0");
  const std::string kernel = fragment ? "fragment " + name + "_out " + name + "(" : "kernel void " + name + "(";
  if (source.find(kernel) == std::string::npos) return "MSL: no '" + kernel + "' in the output";
  // Only the resources the entry point uses become arguments: SPIRV-Cross drops the others
  // (an fp16 or -O0 module keeps a parameter block that no member of it is read from).
  for (const auto& r : module.activeResources(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE)) {
    const unsigned texture = spvc_compiler_msl_get_automatic_resource_binding(c, r.id);
    const unsigned sampler = spvc_compiler_msl_get_automatic_resource_binding_secondary(c, r.id);
    for (const std::string& attr :
         {"[[texture(" + std::to_string(texture) + ")]]", "[[sampler(" + std::to_string(sampler) + ")]]"})
      if (texture == ~0u || sampler == ~0u || source.find(attr) == std::string::npos)
        return std::string("MSL: sampler '") + spvc_compiler_get_name(c, r.id) + "' has no " + attr + " argument";
  }
  for (spvc_resource_type type :
       {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, SPVC_RESOURCE_TYPE_PUSH_CONSTANT})
    for (const auto& r : module.activeResources(type)) {
      const unsigned index = spvc_compiler_msl_get_automatic_resource_binding(c, r.id);
      const std::string attr = "[[buffer(" + std::to_string(index) + ")]]";
      if (index == ~0u || source.find(attr) == std::string::npos)
        return std::string("MSL: buffer '") + spvc_compiler_get_name(c, r.id) + "' has no " + attr + " argument";
    }
  return "";
}

}  // namespace mb
