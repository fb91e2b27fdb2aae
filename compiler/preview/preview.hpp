// matbricks preview as a library (docs/preview.md): a sphere per material, or a row of spheres
// sweeping one parameter, rendered through the permutation's fragment shader in a Vulkan
// graphics pipeline, the same frame rendered on the CPU by the double-precision reference
// composition, the per-pixel comparison against the permutation's tolerance, and the three
// pictures (GPU, reference, difference heatmap). `preview` and `report` both call it.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/environment_mode.hpp"
#include "core/light_type.hpp"
#include "core/precision.hpp"
#include "core/target.hpp"
#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "ltc/ltc_table.hpp"
#include "lut/dfg_lut.hpp"
#include "preview/environment.hpp"
#include "preview/preview_image.hpp"
#include "preview/texel_filter.hpp"
#include "validate/error_metrics.hpp"
#include "validate/probe_ltc_table.hpp"

namespace mb::harness {
class GpuTexture;
}

namespace mb::preview {

inline constexpr uint32_t kMaxPreviewSize = 8192;
inline constexpr uint32_t kDefaultSweepCount = 5;

struct PreviewOptions {
  uint32_t size = 512;                            // pixels per sphere tile edge, 1..kMaxPreviewSize
  std::vector<LightType> lights{LightType::Dir};  // one light each (preview_scene.hpp)
  EnvironmentMode environmentMode = EnvironmentMode::IblLut;
  Precision precision = Precision::Fp32;
  // The language the spheres are drawn in (draw_passes.hpp previewTargets()): SPIR-V on the
  // Vulkan device, or the cross-compiled GLSL 450, ESSL 3.10 (EGL), HLSL (glslang, Vulkan) or
  // WebGL 2.0's ESSL 3.00 (Chromium).
  Target target = Target::Spirv;
  std::string sweep;  // a non-constant parameter of every material; empty: one sphere
  uint32_t sweepCount = kDefaultSweepCount;
  // A brick of the tonemap slot; empty: the one with kernel role "preview_tonemap" (slot.json).
  std::string tonemap;
  double exposure = 1.0;  // radiance scale before the tonemap
  unsigned threads = 0;   // reference render threads; 0: all cores
  // Test hook: model inputs that the reference render alone takes at these values (a wrong
  // reference, which the comparison must catch). Empty in every real use.
  std::map<std::string, std::vector<double>> referenceOverrides;
  // Test hooks for the sampling share (docs/preview.md "Sampling share"): the sampler precision
  // the bound assumes instead of the device's, and a CPU double of fixed-point hardware
  // filtering whose image replaces the GPU's (the reference rendered with its quantized
  // fetches), so that what such a device would draw is judged as the GPU image is.
  std::optional<harness::SamplerPrecision> samplerLimits;
  std::optional<WeightQuantizer> gpuDouble;
};

// The environment a preview lights with, made once and shared by every material rendered
// under it: the maps (CPU side, for the reference), their GPU cube, the DFG LUT and its GPU
// texture.
struct PreviewEnvironment {
  EnvironmentMaps maps;
  lut::LutTable dfg;
  std::shared_ptr<const ProbeLtcTable> ltc;  // the library's LTC tables (the lights shaded by LTC)
  std::shared_ptr<harness::GpuTexture> cube, dfgTexture, ltcTexture;
  double buildMs = 0;  // environment, LUT and uploads
};
// Throws DiagnosticError E-UNKNOWN-ENVIRONMENT for an unknown name (listing the valid ones).
PreviewEnvironment prepareEnvironment(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const std::string& name,
                                      uint32_t cubeSize = 128, uint32_t lutSize = 128);

// Checked before any GPU work (each throws DiagnosticError with a one-line message):
// size in 1..kMaxPreviewSize (E-PREVIEW-SIZE), the tonemap
// brick (E-PREVIEW-TONEMAP), and the sweep parameter of each material (E-PREVIEW-SWEEP,
// listing the material's sweepable parameters); a textured (glTF) material is refused
// (E-PREVIEW-TEXTURED, at the material): its images are not bound yet.
void checkPreviewOptions(const ShaderLibrary& lib, const std::vector<const MaterialDesc*>& materials,
                         const PreviewOptions& options);
// The parameters `--sweep` accepts for `material`: its non-constant parameters.
std::vector<std::string> sweepableParameters(const MaterialDesc& material);

struct ChannelError {
  double maxAbs = 0, meanAbs = 0;
};

struct PreviewResult {
  std::string material, key;  // material name, permutation key
  std::string device;         // what drew the spheres (the Vulkan device, GL_RENDERER, WebGL's renderer)
  uint32_t width = 0, height = 0, spheres = 0;
  std::vector<float> gpu;          // linear radiance, rgb per pixel (background: kBackground)
  std::vector<double> reference;   // the same from the reference render
  std::vector<uint8_t> covered;    // 1 where a sphere covers the pixel
  std::vector<float> position;     // xyz per pixel: the world-space point the pixel shaded (attributes pass)
  std::vector<double> errorRatio;  // per pixel: max over channels of |gpu - ref| / allowed (0 background)
  std::array<ChannelError, 3> channels;
  double maxErrorRatio = 0;
  uint64_t coveredPixels = 0, failures = 0, passedByConditioning = 0, nonFinite = 0;
  Tolerance tolerance;  // abs already scaled by the scene's radiance bound
  double radianceBound = 0;
  // The sampling share of the tolerance (docs/preview.md): the sampler precision it assumes,
  // per pixel rgb the bound on what the device's filtering may change, its largest value, and
  // the largest and mean (over covered pixels) of its ratio to the arithmetic tolerance
  // abs + rel |ref| of the same pixel and channel.
  harness::SamplerPrecision samplerPrecision;
  std::vector<double> samplingBound;
  double samplingMax = 0, samplingOverArithmeticMax = 0, samplingOverArithmeticMean = 0;
  Image8 gpuImage, referenceImage, diffImage;
  // Host times in ms: shader emission and compilation, pipeline creation (lavapipe compiles
  // the shaders there), the two render passes (submit to fence), the reference render, the
  // comparison, and the two tonemaps.
  double compileMs = 0, pipelineMs = 0, renderMs = 0, attributesMs = 0, referenceMs = 0, compareMs = 0, tonemapMs = 0;
  bool passed() const { return failures == 0 && nonFinite == 0 && coveredPixels > 0; }
};

// Linear background radiance of the pictures (a flat mid-dark grey), not judged.
inline constexpr float kBackground[3] = {0.05f, 0.05f, 0.05f};

PreviewResult renderPreview(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const MaterialDesc& material,
                            const PreviewOptions& options, const PreviewEnvironment& environment);

// Writes the GPU picture and, where a path is given (the user named it), the reference and
// difference pictures, each atomically.
void writePreviewImages(const PreviewResult& r, const std::filesystem::path& gpuPng,
                        const std::filesystem::path& referencePng, const std::filesystem::path& diffPng);

}  // namespace mb::preview
