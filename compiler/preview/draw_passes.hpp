// The preview's two passes in the language `--target` names (docs/preview.md "Targets"): the
// permutation's fragment shader, then the attributes shader, over the same draws with the same
// vertex shader. SPIR-V draws with Vulkan (harness/vulkan_graphics.hpp); glsl450 and essl310 are
// the SPIR-V cross-compiled as the package ships them and drawn by the driver's own GLSL compiler
// on EGL (glrun/gl_draw.hpp); webgl2 the same in ESSL 3.00, drawn by WebGL 2.0 in headless
// Chromium (webgl/webgl_draw.hpp); hlsl the package's HLSL compiled back by glslang's HLSL front
// end and drawn with Vulkan.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/target.hpp"
#include "harness/vulkan_harness.hpp"
#include "preview/preview.hpp"
#include "preview/preview_reference.hpp"
#include "preview/sphere_draws.hpp"

namespace mb::preview {

// The three shaders, compiled by glslang to SPIR-V (Vulkan GLSL): every target is made from them.
struct PassShaders {
  std::vector<uint32_t> vertex, fragment, attributes;
  std::string fragmentName;  // the emitted fragment shader's file name, for errors
};

struct DrawnPasses {
  std::vector<float> color;  // RGBA per pixel, row 0 at the top
  PixelAttributes attributes;
  std::string device;  // what drew them
  // Host times in ms: cross-compilation and the driver's compile (or Vulkan's pipelines), the
  // shaded pass and the attributes pass (GL-family targets: both passes in renderMs).
  double pipelineMs = 0, renderMs = 0, attributesMs = 0;
};

// The targets preview draws with: spirv, glsl450, essl310, hlsl, webgl2 (msl: no Metal on Linux).
const std::vector<Target>& previewTargets();

// Throws DiagnosticError (E-TARGET-FAILED) when cross-compilation fails, and the language's
// runner's errors (HarnessError, gl::GlError, webgl::WebglError) as they come.
DrawnPasses drawPasses(Target target, harness::VulkanHarness& gpu, const SphereDraws& draws,
                       const PreviewEnvironment& env, const PassShaders& shaders);

}  // namespace mb::preview
