#include "validate/probe_language.hpp"

#include <chrono>

#include "compile/hlsl_spirv.hpp"
#include "compile/targets.hpp"

namespace mb {
namespace {

[[noreturn]] void fail(const std::string& displayName, const std::string& why) {
  throw DiagnosticError({{Severity::Error, "E-TARGET-FAILED", {displayName, 0, 0}, why}});
}

// The module a package's target is cross-compiled from: the probe's SPIR-V, or for fp16 the
// half module glslang makes (validate runs an emulation of it; the package ships it as is, at
// -O0 as build.cpp compiles fp16 units).
std::vector<uint32_t> shippedModule(const ProbeProgram& p) {
  if (p.precision != ShaderPrecision::Fp16) return p.compiled.spirv;
  CompileOptions o;
  o.optimization = OptimizationLevel::O0;
  return compileComputeGlsl(p.shader.glsl, p.shader.fileName, o).spirv;
}

// The package target whose text a language runs.
Target targetOf(ProbeLanguage language) {
  switch (language) {
    case ProbeLanguage::Spirv:
      return Target::Spirv;
    case ProbeLanguage::Hlsl:
      return Target::Hlsl;
    case ProbeLanguage::Glsl450:
      return Target::Glsl450;
    case ProbeLanguage::Essl310:
      return Target::Essl310;
  }
  return Target::Spirv;
}

}  // namespace

const std::vector<std::string>& executableLanguages() {
  static const std::vector<std::string> names = {"spirv", "hlsl", "glsl450", "essl310"};
  return names;
}

std::optional<ProbeLanguage> parseProbeLanguage(const std::string& name) {
  const auto& names = executableLanguages();
  for (size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<ProbeLanguage>(k);
  return std::nullopt;
}

std::string languageName(ProbeLanguage language) { return executableLanguages().at(static_cast<size_t>(language)); }

bool runsOnVulkan(ProbeLanguage language) {
  return language == ProbeLanguage::Spirv || language == ProbeLanguage::Hlsl;
}

std::string hlslWithPushConstantBlock(const std::string& hlsl, const std::string& displayName) {
  const std::string block = "cbuffer MbPush\n";
  const size_t at = hlsl.find(block);
  if (at == std::string::npos || (at > 0 && hlsl[at - 1] != '\n') || hlsl.find(block, at + 1) != std::string::npos)
    fail(displayName, "target hlsl: expected one 'cbuffer MbPush' block (the record count) in SPIRV-Cross's output");
  return hlsl.substr(0, at) + "[[vk::push_constant]] " + hlsl.substr(at);
}

std::string LanguageProbe::arithmetic() const {
  if (program.precision != ShaderPrecision::Fp16) return program.arithmetic();
  // min16float runs at fp32 on lavapipe (RelaxedPrecision ignored); llvmpipe's GL ES runs
  // mediump in 16-bit floats (docs/targets.md "Executed").
  if (language == ProbeLanguage::Hlsl) return "fp16 as min16float";
  if (language == ProbeLanguage::Essl310) return "fp16 as mediump";
  return program.arithmetic();
}

LanguageProbe translateProbe(ProbeProgram program, ProbeLanguage language, const EmittedShader* mediumpForm) {
  LanguageProbe out;
  out.language = language;
  out.program = std::move(program);
  ProbeProgram& p = out.program;
  if (language == ProbeLanguage::Spirv) return out;
  const auto t0 = std::chrono::steady_clock::now();
  const Target target = targetOf(language);
  const std::string& name = p.shader.fileName;
  if (language == ProbeLanguage::Essl310 && p.precision == ShaderPrecision::Fp16) {
    if (!mediumpForm)
      fail(name, "target essl310: an fp16 probe runs its mediump form, and none was given (ESSL has no 16-bit type)");
    out.source = crossCompile(compileComputeGlsl(mediumpForm->glsl, mediumpForm->fileName).spirv, target, name);
  } else {
    out.source = crossCompile(shippedModule(p), target, name);
  }
  if (language == ProbeLanguage::Hlsl) {
    out.source = hlslWithPushConstantBlock(out.source, name);
    std::vector<uint32_t> spirv;
    const std::string problem = compileHlsl(out.source, spirv);
    if (!problem.empty()) fail(name, "target hlsl: " + problem);
    p.compiled.spirv = std::move(spirv);
    // min16float is fp32 with RelaxedPrecision in glslang's SPIR-V: nothing to emulate.
    p.denormalsKeptSpirv.clear();
  }
  p.compileMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

LanguageProbe buildPermutationProbeIn(const ShaderLibrary& lib, const Permutation& perm, ProbeLanguage language) {
  ProbeProgram p = buildPermutationProbe(lib, perm);
  if (language != ProbeLanguage::Essl310 || p.precision != ShaderPrecision::Fp16)
    return translateProbe(std::move(p), language);
  const EmittedShader mediump = emitPermutation(lib, perm, false, EmitMode::Probe, true);
  return translateProbe(std::move(p), language, &mediump);
}

LanguageProbe buildBrickProbeIn(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant,
                                ShaderPrecision precision, ProbeLanguage language) {
  ProbeProgram p = buildBrickProbe(lib, brick, unstableVariant, precision);
  if (language != ProbeLanguage::Essl310 || precision != ShaderPrecision::Fp16)
    return translateProbe(std::move(p), language);
  const EmittedShader mediump = emitBrickProbe(lib, brick, unstableVariant, ShaderPrecision::Fp16Mediump);
  return translateProbe(std::move(p), language, &mediump);
}

ProbeRun runProbeOn(const ProbeDevices& devices, const LanguageProbe& probe, std::vector<float> inputs) {
  const ProbeProgram& p = probe.program;
  const std::string name = languageName(probe.language);
  if (runsOnVulkan(probe.language)) {
    if (!devices.vulkan) throw harness::HarnessError("no Vulkan device opened for target " + name);
    return runProbeOnGpu(*devices.vulkan, p, std::move(inputs));
  }
  if (!devices.gl) throw gl::GlError("no OpenGL context opened for target " + name);
  gl::GlCompute& gl = *devices.gl;
  const bool es = probe.language == ProbeLanguage::Essl310;
  if (es != (gl.api() == gl::GlApi::Es31))
    throw gl::GlError("target " + name + " needs an " + gl::apiName(es ? gl::GlApi::Es31 : gl::GlApi::Gl45Core) +
                      " context");
  // SPIRV-Cross asks for this extension for 16-bit floats in desktop GLSL; say why rather
  // than pass on the driver's compile error.
  const std::string half = "GL_AMD_gpu_shader_half_float";
  if (probe.source.find("#extension " + half) != std::string::npos && !gl.hasExtension(half))
    throw gl::GlError("\"" + gl.deviceName() + "\" lacks " + half +
                      ", which the glsl450 target uses for fp16: it cannot run fp16 kernels");
  const ProbeLayout& layout = p.shader.layout;
  ProbeRun run;
  run.count = layout.inStride ? inputs.size() / layout.inStride : 0;
  gl::GlRunResult r =
      gl.run(probe.source, inputs, layout.inStride, layout.outStride, run.count, probe.program.tableBuffer());
  run.gpu = std::move(r.outputs);
  run.gpuMs = r.ms;
  run.firstDispatchMs = r.compileMs + r.firstDispatchMs;
  run.inputs = std::move(inputs);
  return run;
}

}  // namespace mb
