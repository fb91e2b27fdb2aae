// validate: a probe run in one of the languages `compile --targets` writes, not only in the
// SPIR-V (docs/targets.md "Executed"). The kernel is the probe's own SPIR-V cross-compiled
// with the compile pipeline's SPIRV-Cross options (compile/targets.hpp), so the text that runs
// is the text a package ships for that kernel:
//   spirv    the probe's SPIR-V on Vulkan (lavapipe), as before
//   hlsl     glslang's HLSL front end compiles the HLSL back to SPIR-V, run on Vulkan (DXC, the
//            HLSL compiler engines use, is not packaged in Debian)
//   glsl450  Mesa's own GLSL compiler in an OpenGL 4.5 core context (glrun/gl_compute.hpp)
//   essl310  Mesa's own GLSL compiler in an OpenGL ES 3.1 context; an fp16 probe runs the
//            permutation's mediump form, as the package's essl310 output is made from it
// MSL has no runtime on Linux and stays structural.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "glrun/gl_compute.hpp"
#include "validate/probe_program.hpp"
#include "validate/validation.hpp"

namespace mb {

enum class ProbeLanguage { Spirv, Hlsl, Glsl450, Essl310 };

// "spirv", "hlsl", "glsl450", "essl310": the targets validate can execute, in that order.
const std::vector<std::string>& executableLanguages();
std::optional<ProbeLanguage> parseProbeLanguage(const std::string& name);
std::string languageName(ProbeLanguage language);
// Whether the language runs on Vulkan (spirv, hlsl) rather than OpenGL (glsl450, essl310).
bool runsOnVulkan(ProbeLanguage language);

// The SPIRV-Cross HLSL of a kernel with a push-constant block (the probe contract's MbPush)
// declares it as a plain `cbuffer`, which glslang (like DXC) compiles for Vulkan as a uniform
// buffer. Root constants are what D3D12 binds it as; on Vulkan the block is a push constant,
// which both front ends spell `[[vk::push_constant]]`: this adds it. Throws DiagnosticError
// when the block is not declared once.
std::string hlslWithPushConstantBlock(const std::string& hlsl, const std::string& displayName);

// A probe in one language. Spirv: `program.compiled` runs. Hlsl: `program.compiled` is the
// module glslang made from `source`. Glsl450, Essl310: `source` runs on OpenGL.
struct LanguageProbe {
  ProbeProgram program;
  ProbeLanguage language = ProbeLanguage::Spirv;
  std::string source;
  // ProbeProgram::arithmetic(), or for an fp16 probe in a language without the fp16
  // emulation what it runs as: "fp16 as min16float" (hlsl), "fp16 as mediump" (essl310).
  std::string arithmetic() const;
};

// `program` in `language`: fills `source` and, for hlsl, replaces the SPIR-V with the module
// glslang compiles from the HLSL. An fp16 probe is cross-compiled from its half module (the
// un-emulated one a package ships); for essl310 it needs `mediumpForm`, the same probe emitted
// with mediump (emitPermutation's `mediump`), and throws without it. compileMs grows by the
// translation's time.
LanguageProbe translateProbe(ProbeProgram program, ProbeLanguage language, const EmittedShader* mediumpForm = nullptr);

// buildPermutationProbe / buildBrickProbe, then translateProbe (the mediump form made here).
LanguageProbe buildPermutationProbeIn(const ShaderLibrary& lib, const Permutation& perm, ProbeLanguage language);
LanguageProbe buildBrickProbeIn(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant,
                                ShaderPrecision precision, ProbeLanguage language);

// What a probe runs on: the Vulkan device for spirv and hlsl, the GL context for glsl450 and
// essl310. A run needs the one its language names.
struct ProbeDevices {
  harness::VulkanHarness* vulkan = nullptr;
  gl::GlCompute* gl = nullptr;
};

// runProbeOnGpu for any language: fills inputs, gpu, gpuMs and firstDispatchMs (on GL: the
// driver's compile and link of a kernel it has not run before, and its first dispatch).
// Throws gl::GlError or harness::HarnessError when the device the language needs is missing.
ProbeRun runProbeOn(const ProbeDevices& devices, const LanguageProbe& probe, std::vector<float> inputs);

// validateProbe (validation.hpp) in the probe's language, on the device it needs. Defined in
// validation.cpp beside validateProbe, whose judging it shares.
ValidationRecord validateProbe(const ProbeDevices& devices, const LanguageProbe& probe, const std::string& kind,
                               uint64_t samples, uint64_t seed, const ReferenceOptions& options = validationOptions());

}  // namespace mb
