#include "preview/draw_passes.hpp"

#include <chrono>
#include <stdexcept>

#include "compile/hlsl_spirv.hpp"
#include "compile/targets.hpp"
#include "core/diagnostics.hpp"
#include "core/descriptor_bindings.hpp"
#include "glrun/gl_draw.hpp"
#include "harness/gpu_texture.hpp"
#include "harness/vulkan_graphics.hpp"
#include "preview/environment_textures.hpp"
#include "webgl/webgl_draw.hpp"

namespace mb::preview {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

DrawnPasses fromTargets(std::vector<float> color, std::vector<std::vector<float>> attributes, uint32_t width,
                        uint32_t height) {
  DrawnPasses out;
  out.color = std::move(color);
  out.attributes = {width,
                    height,
                    std::move(attributes.at(0)),
                    std::move(attributes.at(1)),
                    std::move(attributes.at(2)),
                    std::move(attributes.at(3))};
  return out;
}

DrawnPasses drawOnVulkan(harness::VulkanHarness& gpu, const SphereDraws& d, const PreviewEnvironment& env,
                         const PassShaders& s, uint32_t samplerShift = 0) {
  harness::GraphicsJob job;
  job.separateSamplerShift = samplerShift;
  job.width = d.width;
  job.height = d.height;
  job.mesh = d.mesh;
  for (size_t k = 0; k < d.params.size(); ++k) {
    harness::DrawResources r;
    if (!d.params[k].empty()) r.uniforms.push_back({kFragmentParamsBinding, d.params[k]});
    r.uniforms.push_back({kFragmentFrameBinding, d.frame});
    if (d.prefiltered) r.textures.push_back({kFragmentPrefilteredBinding, {env.cube->view(), env.cube->sampler()}});
    if (d.dfg) r.textures.push_back({kFragmentDfgBinding, {env.dfgTexture->view(), env.dfgTexture->sampler()}});
    if (d.ltc) r.textures.push_back({kFragmentLtcBinding, {env.ltcTexture->view(), env.ltcTexture->sampler()}});
    r.pushConstants = d.vertexBlock;
    r.viewport = {d.tile * static_cast<uint32_t>(k), 0, d.tile, d.tile};
    job.draws.push_back(std::move(r));
  }
  job.vertexSpirv = s.vertex;
  job.fragmentSpirv = s.fragment;
  job.clearColors = {{kBackground[0], kBackground[1], kBackground[2], 0.0f}};
  harness::GraphicsResult shaded = harness::render(gpu, job);
  job.fragmentSpirv = s.attributes;
  job.colorTargets = 4;
  job.clearColors.clear();
  harness::GraphicsResult attributes = harness::render(gpu, job);
  DrawnPasses out = fromTargets(std::move(shaded.targets.at(0)), std::move(attributes.targets), d.width, d.height);
  out.device = gpu.deviceName();
  out.pipelineMs = shaded.pipelineMs + attributes.pipelineMs;
  out.renderMs = shaded.renderMs;
  out.attributesMs = attributes.renderMs;
  return out;
}

// The name the fragment shader gives the block or sampler at `binding` ("" when it has none):
// GL-family APIs bind by name, and the names are the shaders' own (docs/fragment-stage.md).
std::string nameAtBinding(const nlohmann::json& reflection, const char* kind, int binding) {
  for (const auto& r : reflection.value(kind, nlohmann::json::array()))
    if (r.value("binding", -1) == binding) return r.value("name", "");
  return "";
}

gl::DrawJob glJob(const SphereDraws& d, const PreviewEnvironment& env, const PassShaders& s) {
  gl::DrawJob job;
  job.width = d.width;
  job.height = d.height;
  job.mesh.vertices = d.mesh.vertices;
  job.mesh.floatsPerVertex = d.mesh.floatsPerVertex;
  for (const auto& a : d.mesh.attributes) job.mesh.attributes.push_back({a.location, a.components, a.offset});
  job.mesh.indices = d.mesh.indices;
  const nlohmann::json fragment = reflectSpirv(s.fragment), vertex = reflectSpirv(s.vertex);
  const std::string vertexBlock = vertex.at("push_constants").at(0).at("name");
  const std::string params = nameAtBinding(fragment, "uniform_buffers", kFragmentParamsBinding);
  const std::string frame = nameAtBinding(fragment, "uniform_buffers", kFragmentFrameBinding);
  std::map<std::string, size_t> samplers;
  auto addTexture = [&](int binding, gl::DrawTexture texture) {
    const std::string name = nameAtBinding(fragment, "sampled_images", binding);
    if (name.empty()) return;  // optimized away
    samplers[name] = job.textures.size();
    job.textures.push_back(std::move(texture));
  };
  if (d.prefiltered) {
    gl::DrawTexture cube{true, {}};
    for (const CubeLevel& l : env.maps.levels) cube.levels.push_back({l.size, l.size, l.rgba});
    addTexture(kFragmentPrefilteredBinding, std::move(cube));
  }
  if (d.dfg) addTexture(kFragmentDfgBinding, {false, {{env.dfg.size, env.dfg.size, dfgLutTexels(env.dfg)}}});
  if (d.ltc)
    addTexture(kFragmentLtcBinding, {false, {{4 * env.ltc->table.size, env.ltc->table.size, env.ltc->texels}}});
  for (size_t k = 0; k < d.params.size(); ++k) {
    gl::DrawCall call;
    call.uniformBlocks[vertexBlock] = d.vertexBlock;
    if (!frame.empty()) call.uniformBlocks[frame] = d.frame;
    if (!params.empty() && !d.params[k].empty()) call.uniformBlocks[params] = d.params[k];
    call.samplers = samplers;
    call.viewport = {d.tile * static_cast<uint32_t>(k), 0, d.tile, d.tile};
    job.draws.push_back(std::move(call));
  }
  return job;
}

// The GL-family targets: the shaders cross-compiled as the package ships them, then drawn by
// the target's runner.
DrawnPasses drawByName(Target target, const SphereDraws& d, const PreviewEnvironment& env, const PassShaders& s) {
  const auto t0 = Clock::now();
  gl::DrawJob job = glJob(d, env, s);
  job.vertexSource = crossCompile(s.vertex, target, "engine_vertex.vert");  // as the webgl2 package ships it
  job.fragmentSource = crossCompile(s.fragment, target, s.fragmentName);
  const std::string attributesSource = crossCompile(s.attributes, target, "engine_attributes.frag");
  const double crossMs = msSince(t0);
  job.clearColors = {{kBackground[0], kBackground[1], kBackground[2], 0.0f}};
  gl::DrawJob attributesJob = job;
  attributesJob.fragmentSource = attributesSource;
  attributesJob.colorTargets = 4;
  attributesJob.clearColors.clear();
  std::vector<gl::DrawResult> results;
  switch (target) {
    case Target::Glsl450:
    case Target::Essl310: {
      const gl::GlApi api = target == Target::Glsl450 ? gl::GlApi::Gl45Core : gl::GlApi::Es31;
      results.push_back(gl::drawOnGl(api, job));
      results.push_back(gl::drawOnGl(api, attributesJob));
      break;
    }
    case Target::Webgl2:
      results = webgl::drawInBrowser({job, attributesJob});  // one browser for both passes
      break;
    default:
      throw std::logic_error("drawByName: " + targetName(target) + " is not drawn by name");
  }
  gl::DrawResult& shaded = results.at(0);
  gl::DrawResult& attributes = results.at(1);
  DrawnPasses out = fromTargets(std::move(shaded.targets.at(0)), std::move(attributes.targets), d.width, d.height);
  out.device = shaded.device;
  out.pipelineMs = crossMs + shaded.compileMs + attributes.compileMs;
  out.renderMs = shaded.renderMs;
  out.attributesMs = attributes.renderMs;
  return out;
}

// The hlsl target: the fragment and attributes shaders' SPIR-V cross-compiled to the HLSL the
// package ships, compiled back by glslang's HLSL front end (DXC is not in Debian; docs/targets.md)
// with their inputs at the reference vertex shader's locations and samplers at binding + 16, and
// drawn with Vulkan after the SPIR-V vertex shader.
std::vector<uint32_t> hlslFragment(const std::vector<uint32_t>& spirv, const std::string& name) {
  const std::string hlsl = hlslWithInputLocations(crossCompile(spirv, Target::Hlsl, name));
  std::vector<uint32_t> out;
  if (const std::string problem = compileHlsl(hlsl, out, true, kHlslSamplerShift); !problem.empty())
    throw DiagnosticError({{Severity::Error, "E-TARGET-FAILED", {name, 0, 0}, "target hlsl: " + problem}});
  return out;
}

DrawnPasses drawHlsl(harness::VulkanHarness& gpu, const SphereDraws& d, const PreviewEnvironment& env,
                     const PassShaders& s) {
  const auto t0 = Clock::now();
  PassShaders hlsl = s;
  hlsl.fragment = hlslFragment(s.fragment, s.fragmentName);
  hlsl.attributes = hlslFragment(s.attributes, "engine_attributes.frag");
  const double crossMs = msSince(t0);
  DrawnPasses out = drawOnVulkan(gpu, d, env, hlsl, kHlslSamplerShift);
  out.pipelineMs += crossMs;
  return out;
}

}  // namespace

const std::vector<Target>& previewTargets() {
  static const std::vector<Target> targets{Target::Spirv, Target::Glsl450, Target::Essl310, Target::Hlsl,
                                           Target::Webgl2};
  return targets;
}

DrawnPasses drawPasses(Target target, harness::VulkanHarness& gpu, const SphereDraws& draws,
                       const PreviewEnvironment& env, const PassShaders& shaders) {
  if (target == Target::Spirv) return drawOnVulkan(gpu, draws, env, shaders);
  if (target == Target::Hlsl) return drawHlsl(gpu, draws, env, shaders);
  return drawByName(target, draws, env, shaders);
}

}  // namespace mb::preview
