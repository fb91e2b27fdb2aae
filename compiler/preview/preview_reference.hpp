// The preview's reference render (docs/preview.md "Reference"): the frame the GPU shaded,
// evaluated per pixel on the CPU in double by the model's reference composition, from the
// interpolated attributes the attributes pass read back, with the frame built as the
// fragment shader builds it (docs/fragment-stage.md), each light of the scene and the
// environment summed, and the environment fetched through EnvironmentMaps::sample and a CPU
// bilinear lookup of the same DFG LUT texels. Threaded over rows.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/model_reference.hpp"
#include "core/environment_mode.hpp"
#include "ltc/ltc_table.hpp"
#include "lut/dfg_lut.hpp"
#include "preview/environment.hpp"
#include "preview/preview_scene.hpp"
#include "preview/texel_filter.hpp"
#include "validate/probe_ltc_table.hpp"

namespace mb::preview {

// The attributes pass's targets (RGBA32F each, row 0 at the top); position.w = 1 marks a
// covered pixel.
struct PixelAttributes {
  uint32_t width = 0, height = 0;
  std::vector<float> position, normal, tangent, uv;
};

struct ReferenceScene {
  ref::ModelReferenceFn model = nullptr;
  std::map<std::string, std::string> bricks;  // role -> brick id
  std::vector<std::string> features;
  std::vector<LightType> lightTypes;  // the permutation's
  EnvironmentMode environmentMode = EnvironmentMode::None;
  std::vector<PreviewLight> lights;
  const EnvironmentMaps* environment = nullptr;  // IBL and SH modes
  const lut::LutTable* dfg = nullptr;            // ibl_lut
  const ProbeLtcTable* ltc = nullptr;            // the lights shaded by LTC
  // The device's sampler precision, which every fetch's sampling bound assumes, and (test
  // double only) a quantizer that makes the fetches filter as such a device may.
  harness::SamplerPrecision samplerLimits;
  const WeightQuantizer* quantizer = nullptr;
  // Per sphere (tile column): every model input (constants, parameters, and with surface code
  // what surface() computed on the GPU).
  std::vector<std::map<std::string, std::vector<double>>> sphereInputs;
  uint32_t tile = 0;  // pixels per sphere tile edge
};

// What Vulkan's bilinear sampling with clamp-to-edge (the LUT's sampler) returns at (u, v) =
// (NoV, perceptual roughness), in double (Vulkan spec "Texel Filtering": i0 = floor(u size -
// 0.5), weights from the fraction), with its sampling bound (texel_filter.hpp).
FilteredRgb sampleDfgLut(const lut::LutTable& table, double u, double v, const TexelFilter& filter = {});

// The texture fetches of one reference evaluation in call order, and a replay mode that
// returns them again with one fetch's component moved by its sampling bound: how the
// sampling share reaches the pixel (samplingShare).
struct FetchLog {
  std::vector<FilteredRgb> fetches;
  // Per fetch: its channels enter only the same channels of the radiance, linearly (the
  // prefiltered radiance: the specular term is it times a colour), so all three may be moved
  // at once; otherwise (the DFG texel, whose components mix into every channel) one by one.
  std::vector<uint8_t> perChannel;
  bool replay = false;
  size_t next = 0;   // replay: the next fetch to return
  size_t moved = 0;  // replay: the fetch whose component `component` is moved
  int component = 0;
};

// Radiance of one covered pixel (x, y); `work` is referenceWorkspace(scene, sphere of x).
// `perturb` >= 0 selects a sign pattern of conditioningAllowance (-1: the attributes as read).
// The preview has at most one light per type, so one call of the model shades them all.
ref::Vec3 referencePixel(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x, uint32_t y,
                         ref::ModelEvalInput& work, int perturb = -1);

// The reference radiance (rgb per pixel, 0 for background) of every covered pixel; with
// `samplingBound`, also each pixel's sampling share (samplingShare), rgb per pixel.
std::vector<double> referenceImage(const ReferenceScene& scene, const PixelAttributes& a, unsigned threads = 0,
                                   std::vector<double>* samplingBound = nullptr);

// How far the radiance of pixel (x, y) may move when its texture fetches are filtered by any
// device with the scene's sampler precision, per channel: each fetch enters the radiance
// through the shading, so each component's sampling bound is carried to the pixel by
// re-evaluating the shading with that component moved by its bound (the fetches replayed from
// `log`, which the evaluation that gave `reference` recorded; a per-channel fetch's three
// components at once), and the moves are summed. Exact where the radiance is linear in each
// fetched component (the prefiltered radiance is a factor of the specular term), first order
// where it is not (the DFG texel's energy compensation).
std::array<double, 3> samplingShare(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x, uint32_t y,
                                    const ref::Vec3& reference, ref::ModelEvalInput& work, FetchLog& log);

// How far the reference of pixel (x, y) moves when the fragment shader's fp32 direction inputs
// (the interpolated normal and the camera-to-point vector) are perturbed by
// kDirectionInputUlps ulps, over kConditioningPatterns sign patterns (the same backward-error
// allowance validate gives a probe, compiler/validate/probe_program.hpp), per channel.
std::array<double, 3> conditioningAllowance(const ReferenceScene& scene, const PixelAttributes& a, uint32_t x,
                                            uint32_t y, const ref::Vec3& reference, ref::ModelEvalInput& work);

// A working ModelEvalInput for sphere `sphere` of the scene: bricks, features, its inputs, and
// the environment with its fetches bound; with `log`, the fetches record into it (or replay
// from it), and it must outlive the workspace.
ref::ModelEvalInput referenceWorkspace(const ReferenceScene& scene, size_t sphere, FetchLog* log = nullptr);

}  // namespace mb::preview
