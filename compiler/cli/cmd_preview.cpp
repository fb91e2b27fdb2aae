// matbricks preview: render each material's sphere (or a sweep of one parameter) through its
// permutation's fragment shader on the GPU, render the same frame with the double-precision
// reference, compare them per pixel and write the GPU, reference and difference pictures
// (docs/preview.md).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "permute/axes.hpp"
#include "preview/draw_passes.hpp"
#include "preview/preview.hpp"
#include "preview/preview_scene.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct PreviewArgs {
  std::vector<std::string> materials;
  std::string output;
  std::string referenceImage, diffImage;  // with a .png output: only when named
  std::string environment = "studio";
  std::string precision = "fp32";           // options.precision, parsed once the command line is read
  std::string environmentMode = "ibl_lut";  // options.environmentMode, likewise
  std::vector<std::string> lights{"dir"};   // options.lights, checked with the other options
  std::string target = "spirv";             // options.target, likewise
  preview::PreviewOptions options;
  bool json = false;
};

bool endsWithPng(const std::string& path) { return path.size() > 4 && path.compare(path.size() - 4, 4, ".png") == 0; }

[[noreturn]] void previewError(const std::string& code, const std::string& where, const std::string& message) {
  throw DiagnosticError({{Severity::Error, code, {where, 0, 0}, message, ""}});
}

nlohmann::json resultJson(const preview::PreviewResult& r, const std::string& gpuPng) {
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& c : r.channels) channels.push_back({{"max_abs", c.maxAbs}, {"mean_abs", c.meanAbs}});
  return {{"material", r.material},
          {"permutation", r.key},
          {"image", gpuPng},
          {"width", r.width},
          {"height", r.height},
          {"spheres", r.spheres},
          {"covered_pixels", r.coveredPixels},
          {"channels", channels},
          {"max_error_over_tolerance", r.maxErrorRatio},
          {"failures", r.failures},
          {"non_finite", r.nonFinite},
          {"passed_by_conditioning", r.passedByConditioning},
          {"radiance_bound", r.radianceBound},
          {"tolerance", {{"abs", r.tolerance.abs}, {"rel", r.tolerance.rel}, {"reason", r.tolerance.reason}}},
          {"sampling",
           {{"sub_texel_bits", r.samplerPrecision.subTexelBits},
            {"mipmap_bits", r.samplerPrecision.mipmapBits},
            {"max", r.samplingMax},
            {"max_over_arithmetic", r.samplingOverArithmeticMax},
            {"mean_over_arithmetic", r.samplingOverArithmeticMean}}},
          {"compile_ms", r.compileMs},
          {"pipeline_ms", r.pipelineMs},
          {"render_ms", r.renderMs},
          {"attributes_ms", r.attributesMs},
          {"reference_ms", r.referenceMs},
          {"compare_ms", r.compareMs},
          {"tonemap_ms", r.tonemapMs},
          {"drawn_by", r.device},
          {"passed", r.passed()}};
}

void printResult(const preview::PreviewResult& r, const std::string& gpuPng) {
  std::printf("%s (%s): %ux%u, %u sphere%s, %llu pixels compared -> %s\n", r.material.c_str(), r.key.c_str(), r.width,
              r.height, r.spheres, r.spheres == 1 ? "" : "s", static_cast<unsigned long long>(r.coveredPixels),
              gpuPng.c_str());
  static const char* kNames[3] = {"r", "g", "b"};
  for (int c = 0; c < 3; ++c)
    std::printf("  %s: max_abs=%-11.4g mean_abs=%.4g\n", kNames[c], r.channels[c].maxAbs, r.channels[c].meanAbs);
  std::printf(
      "  tolerance abs=%.3g rel=%.3g (radiance bound %.3g); max error/tolerance=%.3g; %llu outside, %llu "
      "non-finite\n",
      r.tolerance.abs, r.tolerance.rel, r.radianceBound, r.maxErrorRatio, static_cast<unsigned long long>(r.failures),
      static_cast<unsigned long long>(r.nonFinite));
  std::printf(
      "  sampling share (subTexelPrecisionBits %u, mipmapPrecisionBits %u): max %.3g; over the arithmetic "
      "tolerance max %.3g, mean %.3g\n",
      r.samplerPrecision.subTexelBits, r.samplerPrecision.mipmapBits, r.samplingMax, r.samplingOverArithmeticMax,
      r.samplingOverArithmeticMean);
  std::printf("  drawn by %s\n", r.device.c_str());
  std::printf(
      "  compile %.0f ms, pipelines %.0f ms, render %.0f ms, attributes %.0f ms, reference %.0f ms, "
      "tonemap %.0f ms: %s\n",
      r.compileMs, r.pipelineMs, r.renderMs, r.attributesMs, r.referenceMs, r.tonemapMs, r.passed() ? "PASS" : "FAIL");
}

int runPreview(PreviewArgs& a, const GlobalOptions& g) {
  a.options.precision = *parsePrecision(a.precision);                    // checked by --precision's IsMember
  a.options.environmentMode = *parseEnvironmentMode(a.environmentMode);  // checked by --environment-mode's IsMember
  a.options.target = *parseTarget(a.target);                             // checked by --target's IsMember
  const ShaderLibrary lib = loadLibrary(g);
  const std::vector<MaterialDesc> materials = loadMaterials(a.materials, lib, g);
  std::vector<const MaterialDesc*> pointers;
  for (const auto& m : materials) pointers.push_back(&m);
  // Everything the command line decides is checked before the device opens or a file is written.
  const std::vector<std::string> envs = preview::environmentNames();
  if (std::find(envs.begin(), envs.end(), a.environment) == envs.end()) {
    std::string list;
    for (const auto& e : envs) list += (list.empty() ? "" : ", ") + e;
    throw DiagnosticError({{Severity::Error,
                            "E-UNKNOWN-ENVIRONMENT",
                            {"<command line>", 0, 0},
                            "unknown environment '" + a.environment + "' (valid: " + list + ")",
                            didYouMean(a.environment, envs)}});
  }
  a.options.lights = preview::parsePreviewLights(a.lights);  // E-PREVIEW-LIGHT
  preview::checkPreviewOptions(lib, pointers, a.options);
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  addMaterialInputs(inputs, materials);
  const bool singleFile = endsWithPng(a.output);
  if (singleFile) {
    if (materials.size() != 1)
      previewError("E-PREVIEW-OUTPUT", a.output,
                   "a .png output takes exactly one material (got " + std::to_string(materials.size()) +
                       "); give a directory to preview several");
    // Each picture goes only where the user named it; none may be another's path.
    for (const auto& [file, what] :
         {std::pair{&a.output, "preview image"}, std::pair{&a.referenceImage, "reference image"},
          std::pair{&a.diffImage, "difference image"}}) {
      if (file->empty()) continue;
      checkFileOutput(*file, what, inputs);
      if (!endsWithPng(*file))
        previewError("E-PREVIEW-OUTPUT", *file, std::string("the ") + what + " must be a .png file");
      inputs.push_back({*file, what});
    }
  } else {
    if (!a.referenceImage.empty() || !a.diffImage.empty())
      previewError("E-PREVIEW-OUTPUT", a.referenceImage.empty() ? a.diffImage : a.referenceImage,
                   "--reference-image and --diff-image go with a .png output; an output directory holds every "
                   "material's reference and difference pictures");
    checkDirectoryOutput(a.output, inputs);
  }

  auto gpu = openDevice(g);
  const preview::PreviewEnvironment env = preview::prepareEnvironment(*gpu, lib, a.environment);
  std::vector<preview::PreviewResult> results;
  for (const auto& m : materials) results.push_back(preview::renderPreview(*gpu, lib, m, a.options, env));
  const bool layerMessages = reportLayerMessages(*gpu);

  // The pictures are written whether or not the comparison passed: the difference image is
  // what shows where it failed. They are written only after every material rendered.
  nlohmann::json out = nlohmann::json::array();
  if (singleFile) {
    const auto& r = results.front();
    preview::writePreviewImages(r, a.output, a.referenceImage, a.diffImage);
  } else {
    PackageWriter w("preview");
    for (const auto& r : results) {
      w.addFile(r.material + ".png", preview::encodePng(r.gpuImage));
      w.addFile(r.material + ".reference.png", preview::encodePng(r.referenceImage));
      w.addFile(r.material + ".diff.png", preview::encodePng(r.diffImage));
    }
    w.commit(a.output);
  }
  bool ok = !layerMessages;
  for (const auto& r : results) {
    const std::string png = singleFile ? a.output : a.output + "/" + r.material + ".png";
    ok = ok && r.passed();
    if (a.json)
      out.push_back(resultJson(r, png));
    else
      printResult(r, png);
  }
  if (a.json) {
    std::cout
        << nlohmann::json{{"environment", a.environment}, {"target", a.target}, {"environment_build_ms", env.buildMs},
                          {"device", gpu->deviceName()},  {"previews", out},    {"passed", ok}}
               .dump(2)
        << "\n";
  } else {
    std::printf("environment %s built in %.0f ms on %s; %s\n", a.environment.c_str(), env.buildMs,
                gpu->deviceName().c_str(), ok ? "passed" : "FAILED: GPU pixels outside the reference's tolerance");
  }
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addPreviewCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<PreviewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "preview", "Render materials on spheres through their fragment shaders, and compare with the reference render");
  cmd->add_option("materials", args->materials, kMaterialFilesHelp)->required();
  cmd->add_option("-o,--output", args->output,
                  "Directory (new, empty or matbricks-written) for <material>.png, .reference.png and .diff.png, or "
                  "one X.png (one material; the GPU picture only, see --reference-image and --diff-image)")
      ->required();
  cmd->add_option("--reference-image", args->referenceImage,
                  "With -o X.png: also write the CPU reference picture to this .png file");
  cmd->add_option("--diff-image", args->diffImage,
                  "With -o X.png: also write the difference heatmap to this .png file");
  cmd->add_option("--size", args->options.size, "Pixels per sphere tile edge (default 512, at most 8192)");
  cmd->add_option("--environment", args->environment, "Environment: studio (default) or sky");
  cmd->add_option("--lights", args->lights,
                  "Light types, one light each: dir,point,spot,sphere,tube,rect,disk (default: dir)")
      ->delimiter(',');
  cmd->add_option("--environment-mode", args->environmentMode, "The permutation's environment mode (default: ibl_lut)")
      ->check(CLI::IsMember(allEnvironmentModeNames()));
  cmd->add_option("--target", args->target,
                  "Language the spheres are drawn in: spirv (default; the Vulkan device), glsl450 or essl310 (the "
                  "driver's GLSL compiler, OpenGL 4.5 core / ES 3.1 through EGL), hlsl (glslang's HLSL front end, "
                  "then Vulkan) or webgl2 (WebGL 2.0 in headless Chromium). docs/preview.md")
      ->check(CLI::IsMember(targetNames(preview::previewTargets())));
  cmd->add_option("--precision", args->precision, "The permutation's precision (default: fp32)")
      ->check(CLI::IsMember(allPrecisionNames()));
  cmd->add_option("--sweep", args->options.sweep, "A row of spheres sweeping this parameter over its range");
  cmd->add_option("--sweep-count", args->options.sweepCount, "Spheres in a sweep (default 5, 2..16)");
  cmd->add_option(
      "--tonemap", args->options.tonemap,
      "Tonemap brick (default: the library's brick with kernel role preview_tonemap, tonemap_aces_narkowicz)");
  cmd->add_option("--exposure", args->options.exposure, "Radiance scale before the tonemap (default 1)");
  cmd->add_option("-j,--threads", args->options.threads, "Reference render threads (default: all cores)");
  cmd->add_flag("--json", args->json, "JSON report");
  return {cmd, [args, &g] { return runPreview(*args, g); }};
}

}  // namespace mb::cli
