// renderPreview (preview.hpp): the permutation, its spheres' parameters, the two graphics
// passes, the reference render, the comparison and the pictures.
#include "preview/preview.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/reference.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/reference_vertex.hpp"
#include "core/diagnostics.hpp"
#include "emit/fragment_shader.hpp"
#include "emit/fragment_textures.hpp"
#include "harness/gpu_texture.hpp"
#include "harness/vulkan_graphics.hpp"
#include "lut/lut_gpu.hpp"
#include "permute/permutation.hpp"
#include "preview/environment_textures.hpp"
#include "preview/preview_reference.hpp"
#include "preview/preview_scene.hpp"
#include "preview/draw_passes.hpp"
#include "preview/sphere_draws.hpp"
#include "validate/probe_program.hpp"

namespace mb::preview {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

[[noreturn]] void optionError(const std::string& code, const std::string& message, const std::string& suggestion = {}) {
  throw DiagnosticError({{Severity::Error, code, {"<command line>", 0, 0}, message, suggestion}});
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::vector<SphereParams> sphereParams(const MaterialDesc& m, const PreviewOptions& o) {
  const uint32_t count = o.sweep.empty() ? 1 : std::max(o.sweepCount, 1u);
  std::vector<SphereParams> spheres(count);
  for (uint32_t i = 0; i < count; ++i) {
    for (const auto& prm : m.params) {
      if (prm.constant) continue;
      std::vector<double> v = prm.value;
      if (prm.name == o.sweep) {
        // Evenly over the parameter's range, both ends included.
        const double t = count == 1 ? 0.5 : static_cast<double>(i) / (count - 1);
        for (double& c : v) c = prm.range.lo + (prm.range.hi - prm.range.lo) * t;
      }
      spheres[i][prm.name] = v;
    }
  }
  return spheres;
}

// `optimization`: O0 for a module with 16-bit floats, as the package builds them (spirv-opt's
// folding of SPIRV-Tools v2023.1 emits 16-bit constants spirv-val rejects; docs/targets.md).
std::vector<uint32_t> compileStage(const std::string& glsl, const std::string& name, ShaderStage stage,
                                   OptimizationLevel optimization = OptimizationLevel::O2) {
  CompileOptions options;
  options.stage = stage;
  options.optimization = optimization;
  return compileComputeGlsl(glsl, name, options).spirv;
}

// The model inputs of each sphere for the reference: the material's constants and the
// sphere's parameters, and with surface code what surface() computed on the GPU (the compute
// probe of the same permutation, one record per sphere: there is no C++ form of user GLSL).
std::vector<std::map<std::string, std::vector<double>>> sphereModelInputs(harness::VulkanHarness& gpu,
                                                                          const ShaderLibrary& lib,
                                                                          const Permutation& perm,
                                                                          const std::vector<SphereParams>& spheres) {
  const MaterialDesc& m = *perm.material;
  std::vector<std::map<std::string, std::vector<double>>> out(spheres.size());
  for (size_t s = 0; s < spheres.size(); ++s) {
    for (const auto& prm : m.params)
      if (!prm.user) out[s][prm.name] = prm.constant ? prm.value : spheres[s].at(prm.name);
  }
  if (!m.surface.present()) return out;
  const ProbeProgram probe = buildPermutationProbe(lib, perm);
  const ProbeLayout& layout = probe.shader.layout;
  std::vector<float> records = generateSamples(layout, probe.domain, spheres.size(), 1);
  for (size_t s = 0; s < spheres.size(); ++s) {
    for (const auto& prm : m.params) {
      if (prm.constant) continue;
      const ProbeInput* in = layout.find(prm.name);
      for (int k = 0; k < componentCount(prm.type); ++k)
        records[s * layout.inStride + in->offset + k] = static_cast<float>(spheres[s].at(prm.name)[k]);
    }
  }
  const ProbeRun run = runProbeOnGpu(gpu, probe, std::move(records));
  for (size_t s = 0; s < spheres.size(); ++s) {
    for (const auto& f : layout.fedOutputs) {
      const float* v = run.gpu.data() + s * layout.outStride + f.offset;
      out[s][f.name].assign(v, v + componentCount(f.type));
    }
  }
  return out;
}

// Display values: exposure, the tonemap brick, the sRGB OETF. The GPU image goes through the
// brick's GLSL on the device (its compute probe), the reference image through its C++
// reference in double.
// The tonemap brick: --tonemap, else the library's brick with kernel role "preview_tonemap"
// (empty when it has none: checkPreviewOptions refuses that).
std::string tonemapBrick(const ShaderLibrary& lib, const PreviewOptions& o) {
  if (!o.tonemap.empty()) return o.tonemap;
  const Brick* b = lib.brickForKernelRole("preview_tonemap");
  return b ? b->id : std::string();
}

Image8 tonemapGpu(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const PreviewOptions& o,
                  const std::vector<float>& rgb, uint32_t width, uint32_t height) {
  const std::string id = tonemapBrick(lib, o);
  const ProbeProgram probe = buildBrickProbe(lib, *lib.findBrick(id));
  if (probe.shader.layout.inStride != 3 || probe.shader.layout.outStride != 3)
    throw std::logic_error("tonemap brick '" + id + "' is not vec3 -> vec3");
  std::vector<float> in(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) in[i] = static_cast<float>(rgb[i] * o.exposure);
  const ProbeRun run = runProbeOnGpu(gpu, probe, std::move(in));
  Image8 image{width, height, 3, std::vector<uint8_t>(rgb.size())};
  for (size_t i = 0; i < rgb.size(); ++i) image.pixels[i] = encodeSrgb8(run.gpu[i]);
  return image;
}

Image8 tonemapReference(const ShaderLibrary& lib, const PreviewOptions& o, const std::vector<double>& rgb,
                        uint32_t width, uint32_t height) {
  const std::string id = tonemapBrick(lib, o);
  const ref::Reference* tonemap = ref::Registry::references().find(id);
  if (!tonemap) throw std::logic_error("tonemap brick '" + id + "' has no reference");
  Image8 image{width, height, 3, std::vector<uint8_t>(rgb.size())};
  for (size_t p = 0; p < rgb.size() / 3; ++p) {
    const double in[3] = {rgb[p * 3] * o.exposure, rgb[p * 3 + 1] * o.exposure, rgb[p * 3 + 2] * o.exposure};
    double out[3] = {0, 0, 0};
    tonemap->eval(in, out);
    for (int c = 0; c < 3; ++c) image.pixels[p * 3 + c] = encodeSrgb8(out[c]);
  }
  return image;
}

// Per pixel and channel: |gpu - ref| against abs + rel |ref|, widened by the fp32 direction
// conditioning only where the arithmetic bound alone does not pass (validate's
// onlyWhereNeeded: the same verdicts at a fraction of the cost).
void compare(const ReferenceScene& scene, const PixelAttributes& attributes, PreviewResult& r) {
  const size_t pixels = size_t{r.width} * r.height;
  r.errorRatio.assign(pixels, 0.0);
  double sum[3] = {0, 0, 0}, samplingRatioSum = 0;
  std::vector<ref::ModelEvalInput> work;
  for (size_t s = 0; s < scene.sphereInputs.size(); ++s) work.push_back(referenceWorkspace(scene, s));
  for (size_t p = 0; p < pixels; ++p) {
    if (!r.covered[p]) continue;
    ++r.coveredPixels;
    double ratio = 0, samplingRatio = 0;
    bool conditioned = false;
    std::array<double, 3> allowance{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      const double g = r.gpu[p * 3 + c], ref = r.reference[p * 3 + c];
      if (!std::isfinite(g) || !std::isfinite(ref)) {
        ++r.nonFinite;
        ratio = std::numeric_limits<double>::infinity();
        continue;
      }
      const double err = std::abs(g - ref);
      r.channels[c].maxAbs = std::max(r.channels[c].maxAbs, err);
      sum[c] += err;
      const double arithmetic = r.tolerance.abs + r.tolerance.rel * std::abs(ref);
      const double sampling = r.samplingBound[p * 3 + c];
      samplingRatio = std::max(samplingRatio, arithmetic > 0 ? sampling / arithmetic : 0.0);
      double allowed = arithmetic + sampling;
      if (err > allowed && !conditioned) {
        const uint32_t x = static_cast<uint32_t>(p % r.width), y = static_cast<uint32_t>(p / r.width);
        const ref::Vec3 reference{r.reference[p * 3], r.reference[p * 3 + 1], r.reference[p * 3 + 2]};
        allowance = conditioningAllowance(scene, attributes, x, y, reference, work.at(x / scene.tile));
        conditioned = true;
      }
      const bool failedAlone = err > allowed;
      allowed += allowance[c];
      if (failedAlone && err <= allowed) ++r.passedByConditioning;
      const double e = allowed > 0 ? err / allowed : (err > 0 ? std::numeric_limits<double>::infinity() : 0.0);
      ratio = std::max(ratio, e);
    }
    r.errorRatio[p] = ratio;
    r.maxErrorRatio = std::max(r.maxErrorRatio, ratio);
    r.samplingOverArithmeticMax = std::max(r.samplingOverArithmeticMax, samplingRatio);
    samplingRatioSum += samplingRatio;
    if (ratio > 1.0) ++r.failures;
  }
  for (int c = 0; c < 3; ++c) r.channels[c].meanAbs = r.coveredPixels ? sum[c] / r.coveredPixels : 0.0;
  r.samplingOverArithmeticMean = r.coveredPixels ? samplingRatioSum / r.coveredPixels : 0.0;
}

Image8 heatmap(const PreviewResult& r) {
  Image8 image{r.width, r.height, 3, std::vector<uint8_t>(size_t{r.width} * r.height * 3, 40)};
  for (size_t p = 0; p < r.covered.size(); ++p)
    if (r.covered[p]) heatmapColor(r.errorRatio[p], &image.pixels[p * 3]);
  return image;
}

}  // namespace

std::vector<std::string> sweepableParameters(const MaterialDesc& material) {
  std::vector<std::string> names;
  for (const auto& prm : material.params)
    if (!prm.constant) names.push_back(prm.name);
  return names;
}

void checkPreviewOptions(const ShaderLibrary& lib, const std::vector<const MaterialDesc*>& materials,
                         const PreviewOptions& o) {
  if (o.size == 0 || o.size > kMaxPreviewSize)
    optionError("E-PREVIEW-SIZE",
                "--size " + std::to_string(o.size) + " is outside 1.." + std::to_string(kMaxPreviewSize) + " pixels");
  const Brick* tonemap = lib.findBrick(tonemapBrick(lib, o));
  if (!tonemap || tonemap->slot != "tonemap") {
    std::vector<std::string> valid;
    for (const auto& b : lib.bricks())
      if (b.slot == "tonemap") valid.push_back(b.id);
    if (o.tonemap.empty())
      optionError("E-PREVIEW-TONEMAP",
                  "no --tonemap given, and no brick of the library has kernel role 'preview_tonemap' (valid: " +
                      joined(valid) + ")",
                  "");
    optionError("E-PREVIEW-TONEMAP", "unknown tonemap brick '" + o.tonemap + "' (valid: " + joined(valid) + ")",
                didYouMean(o.tonemap, valid));
  }
  for (const MaterialDesc* m : materials) {
    // The fragment shader samples a glTF material's images at bindings 4+; the preview does not
    // upload them (nor has the reference a CPU sampler for them) yet.
    const size_t textures = fragmentTextures(*m).size();
    if (textures)
      throw DiagnosticError({{Severity::Error, "E-PREVIEW-TEXTURED", m->modelWhere,
                              "material '" + m->name + "' samples " + std::to_string(textures) +
                                  " texture(s); preview does not bind material textures yet",
                              ""}});
  }
  if (o.sweep.empty()) return;
  if (o.sweepCount < 2 || o.sweepCount > 16)
    optionError("E-PREVIEW-SWEEP", "--sweep-count " + std::to_string(o.sweepCount) + " is outside 2..16");
  for (const MaterialDesc* m : materials) {
    const std::vector<std::string> valid = sweepableParameters(*m);
    if (std::find(valid.begin(), valid.end(), o.sweep) == valid.end())
      optionError("E-PREVIEW-SWEEP",
                  "material '" + m->name + "' has no non-constant parameter '" + o.sweep +
                      "' to sweep (valid: " + (valid.empty() ? std::string("none") : joined(valid)) + ")",
                  didYouMean(o.sweep, valid));
  }
}

PreviewEnvironment prepareEnvironment(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const std::string& name,
                                      uint32_t cubeSize, uint32_t lutSize) {
  const auto t0 = Clock::now();
  PreviewEnvironment env;
  env.maps = buildEnvironment(lib, name, gpu, cubeSize);
  env.dfg = lut::generateDfgLutOnGpu(gpu, lib, lutSize, 0).table;
  env.cube = uploadEnvironmentCube(gpu, env.maps);
  env.dfgTexture = uploadDfgLut(gpu, env.dfg);
  env.ltc = probeLtcTable(lib);
  env.ltcTexture = uploadLtcTable(gpu, *env.ltc);
  env.buildMs = msSince(t0);
  return env;
}

PreviewResult renderPreview(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const MaterialDesc& material,
                            const PreviewOptions& o, const PreviewEnvironment& env) {
  checkPreviewOptions(lib, {&material}, o);
  Permutation perm;
  perm.material = &material;
  perm.lights = canonicalLights(o.lights);
  perm.environment = o.environmentMode;
  perm.precision = o.precision;
  const std::vector<PreviewLight> lights = defaultLights(perm.lights);
  const std::vector<SphereParams> spheres = sphereParams(material, o);

  PreviewResult r;
  r.material = material.name;
  r.key = perm.key();
  r.spheres = static_cast<uint32_t>(spheres.size());

  auto t0 = Clock::now();
  // A language without 16-bit floats (essl310, webgl2) runs an fp16 permutation's mediump form,
  // as the package ships it (docs/targets.md "fp16 permutations").
  const bool mediump = perm.precision == Precision::Fp16 && !targetInfo(o.target).float16;
  const EmittedShader fragment = emitFragmentShader(lib, perm, mediump);
  const SphereDraws draws = sphereDraws(o, material, spheres, lights, perm.environment, env.maps);
  PassShaders shaders;
  shaders.vertex = referenceVertexSpirv(lib);
  const bool float16 = perm.precision == Precision::Fp16 && !mediump;
  shaders.fragment = compileStage(fragment.glsl, fragment.fileName, ShaderStage::Fragment,
                                  float16 ? OptimizationLevel::O0 : OptimizationLevel::O2);
  shaders.attributes =
      compileStage(lib.source("common/engine_attributes.frag"), "engine_attributes.frag", ShaderStage::Fragment);
  shaders.fragmentName = fragment.fileName;
  r.compileMs = msSince(t0);
  r.width = draws.width;
  r.height = draws.height;

  // Pass 1: the permutation's fragment shader; pass 2: the same draws with the attributes shader.
  DrawnPasses drawn = drawPasses(o.target, gpu, draws, env, shaders);
  r.device = drawn.device;
  r.pipelineMs = drawn.pipelineMs;
  r.renderMs = drawn.renderMs;
  r.attributesMs = drawn.attributesMs;
  PixelAttributes a = std::move(drawn.attributes);

  const size_t pixels = size_t{r.width} * r.height;
  r.gpu.resize(pixels * 3);
  r.covered.resize(pixels);
  r.position.resize(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    r.covered[p] = a.position[p * 4 + 3] == 1.0f;
    for (int c = 0; c < 3; ++c) {
      r.gpu[p * 3 + c] = drawn.color[p * 4 + c];
      r.position[p * 3 + c] = a.position[p * 4 + c];
    }
  }

  ReferenceScene scene;
  scene.model = ref::ModelRegistry::instance().find(material.model);
  if (!scene.model) throw std::logic_error("model '" + material.model + "' has no reference composition");
  for (const auto& [role, id] : boundRoles(lib, perm)) scene.bricks[role] = id;
  scene.features = material.features;
  scene.lightTypes = perm.lights;
  scene.environmentMode = perm.environment;
  scene.lights = lights;
  scene.environment = &env.maps;
  scene.dfg = &env.dfg;
  scene.ltc = env.ltc.get();
  // GL and WebGL expose no sampler precision: their bound assumes the least Vulkan allows.
  const harness::SamplerPrecision device =
      o.target == Target::Spirv ? harness::samplerPrecision(gpu) : harness::SamplerPrecision{};
  scene.samplerLimits = r.samplerPrecision = o.samplerLimits.value_or(device);
  scene.tile = o.size;
  scene.sphereInputs = sphereModelInputs(gpu, lib, perm, spheres);
  for (auto& inputs : scene.sphereInputs)
    for (const auto& [name, value] : o.referenceOverrides) inputs[name] = value;

  t0 = Clock::now();
  r.reference = referenceImage(scene, a, o.threads, &r.samplingBound);
  for (size_t p = 0; p < pixels; ++p)
    if (!r.covered[p])
      for (int c = 0; c < 3; ++c) r.reference[p * 3 + c] = kBackground[c];
  r.samplingMax = *std::max_element(r.samplingBound.begin(), r.samplingBound.end());
  if (o.gpuDouble) {
    ReferenceScene device = scene;
    device.quantizer = &*o.gpuDouble;
    const std::vector<double> drawn = referenceImage(device, a, o.threads);
    for (size_t p = 0; p < pixels; ++p)
      if (r.covered[p])
        for (int c = 0; c < 3; ++c) r.gpu[p * 3 + c] = static_cast<float>(drawn[p * 3 + c]);
  }
  r.referenceMs = msSince(t0);

  r.radianceBound = sceneRadianceBound(lights, perm.environment == EnvironmentMode::None ? nullptr : &env.maps);
  r.tolerance = compositionTolerance(lib, perm, fragment.bricks, r.radianceBound);
  t0 = Clock::now();
  compare(scene, a, r);
  r.compareMs = msSince(t0);

  t0 = Clock::now();
  r.gpuImage = tonemapGpu(gpu, lib, o, r.gpu, r.width, r.height);
  r.referenceImage = tonemapReference(lib, o, r.reference, r.width, r.height);
  r.diffImage = heatmap(r);
  r.tonemapMs = msSince(t0);
  return r;
}

void writePreviewImages(const PreviewResult& r, const std::filesystem::path& gpuPng,
                        const std::filesystem::path& referencePng, const std::filesystem::path& diffPng) {
  writePng(gpuPng, r.gpuImage);
  if (!referencePng.empty()) writePng(referencePng, r.referenceImage);
  if (!diffPng.empty()) writePng(diffPng, r.diffImage);
}

}  // namespace mb::preview
