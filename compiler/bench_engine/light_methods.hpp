// Each area-light shape by each method a model offers for it, run time against error
// (docs/models/lights.md "Light methods: run time against error"): bench's permutation cost of
// the material with that one light (its frame, the light and, for the LTC methods, the table's
// fetches, over the validation probe's sampled lights), against the method's error in double:
// the model's reference for the material made a metal of base colour 1 (so the specular lobe;
// no environment, so no compensation), over the brute-force integral of the lobe over the
// light (common/area_light_truth.hpp, common/ltc_reference.hpp). `mb_bench_light_methods` and
// the report draw it.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_engine/bench_runner.hpp"
#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"

namespace mb::bench {

struct LightMethodRow {
  LightType light = LightType::Sphere;
  std::string method;  // "" where the model offers one way only
  bool readsLtcTable = false;
  CostMeasurement cost;
  int lights = 0;                                      // drawn lights the error is taken over
  double errorMedian = 0, errorP95 = 0, errorMax = 0;  // of |ours / integral - 1|
};

struct LightMethodOptions {
  int lights = 400;  // per row
  uint64_t seed = 1;
  CostOptions cost;
};

// True when the rows can be measured for `material`: its model shades a sphere, tube, rectangle
// or disk light and has the standard model's metallic and baseColor inputs.
bool hasLightMethods(const ShaderLibrary& lib, const MaterialDesc& material);
// The sphere, tube, rectangle and disk lights among `lights`, in axis order.
std::vector<LightType> areaLightsOf(const std::vector<LightType>& lights);
// One row per method of each of those light types the model shades (of `only`, when it is not
// empty), in axis order.
std::vector<LightMethodRow> measureLightMethods(harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                                const MaterialDesc& material, const LightMethodOptions& options,
                                                const std::vector<LightType>& only = {});

// "sphere: ltc", or "rect" where there is one way only.
std::string lightMethodLabel(const LightMethodRow& row);
nlohmann::json toJson(const std::vector<LightMethodRow>& rows);
// x: ns per evaluation (the 95 % interval as a bar), y: median |ratio - 1| (the mark) up to the
// 95th percentile (dashed), both logarithmic; circles read the LTC table, squares do not.
std::string lightMethodsSvg(const std::vector<LightMethodRow>& rows, const std::string& subtitle);
std::string lightMethodsMarkdown(const std::vector<LightMethodRow>& rows);

}  // namespace mb::bench
