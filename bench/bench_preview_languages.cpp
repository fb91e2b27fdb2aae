// The preview in every language it draws (docs/targets.md "Executed", docs/preview.md "Targets"):
// each material's sphere at SIZE pixels, studio environment, ibl_lut, the given lights, drawn as
// spirv (Vulkan), glsl450 and essl310 (Mesa's GL on EGL), hlsl (glslang's HLSL front end, Vulkan)
// and webgl2 (WebGL 2.0 in headless Chromium), each compared with the double reference at the
// attributes its own pass read back. Per language: the largest error ratio (|gpu - ref| /
// allowed; 1 = the tolerance) and absolute error over the materials, and the medians of the draw
// (translation, the driver's compile or Vulkan's pipelines, both passes) in ms.
//
// Usage: mb_bench_preview_languages SIZE LIGHTS MATERIAL...   (LIGHTS e.g. dir or dir,rect)
// One process, the environment built once; the load average is recorded before and after.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "bench_stats.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "preview/draw_passes.hpp"
#include "preview/preview.hpp"
#include "preview/preview_scene.hpp"

using namespace mb;

namespace {

using mb::bench::median;

using mb::bench::loadAverage;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: mb_bench_preview_languages SIZE LIGHTS MATERIAL...\n";
    return 2;
  }
  preview::PreviewOptions base;
  base.size = static_cast<uint32_t>(std::atoi(argv[1]));
  base.lights = preview::parsePreviewLights(split(argv[2]));
  const std::string loadBefore = loadAverage();
  const ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  std::vector<MaterialDesc> materials;
  for (int i = 3; i < argc; ++i) materials.push_back(loadMaterialJson(argv[i], lib));
  harness::VulkanHarness gpu;
  const preview::PreviewEnvironment env = preview::prepareEnvironment(gpu, lib, "studio");

  nlohmann::json languages = nlohmann::json::object();
  bool passed = true;
  for (Target target : preview::previewTargets()) {
    preview::PreviewOptions o = base;
    o.target = target;
    double maxRatio = 0, maxAbs = 0;
    std::vector<double> drawMs, pipelineMs, renderMs;
    std::string device;
    nlohmann::json perMaterial = nlohmann::json::object();
    for (const auto& m : materials) {
      const preview::PreviewResult r = preview::renderPreview(gpu, lib, m, o, env);
      passed = passed && r.passed();
      maxRatio = std::max(maxRatio, r.maxErrorRatio);
      for (const auto& c : r.channels) maxAbs = std::max(maxAbs, c.maxAbs);
      drawMs.push_back(r.pipelineMs + r.renderMs + r.attributesMs);
      pipelineMs.push_back(r.pipelineMs);
      renderMs.push_back(r.renderMs);
      device = r.device;
      perMaterial[m.name] = {
          {"max_error_over_tolerance", r.maxErrorRatio}, {"covered_pixels", r.coveredPixels}, {"passed", r.passed()}};
    }
    languages[targetName(target)] = {{"device", device},
                                     {"max_error_over_tolerance", maxRatio},
                                     {"max_abs", maxAbs},
                                     {"draw_ms_median", median(drawMs)},
                                     {"pipeline_ms_median", median(pipelineMs)},
                                     {"render_ms_median", median(renderMs)},
                                     {"materials", std::move(perMaterial)}};
  }
  std::cout << nlohmann::json{{"size", base.size},
                              {"lights", argv[2]},
                              {"environment", "studio"},
                              {"environment_mode", "ibl_lut"},
                              {"materials", materials.size()},
                              {"vulkan_device", gpu.deviceName()},
                              {"load_before", loadBefore},
                              {"load_after", loadAverage()},
                              {"languages", std::move(languages)},
                              {"passed", passed}}
                   .dump(2)
            << "\n";
  return passed ? 0 : 1;
}
