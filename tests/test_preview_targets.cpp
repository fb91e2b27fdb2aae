// preview --target (docs/preview.md "Targets"): the spheres drawn through the GLSL 450 and ESSL
// 3.10 a package ships, by Mesa's own GLSL compiler on EGL, through its HLSL compiled back by
// glslang's HLSL front end, and through the webgl2 target's ESSL 3.00 in WebGL 2.0 in headless
// Chromium; each picture within the tolerance of the double
// reference evaluated at the attributes that language's own pass read back, and those attributes
// the same surface points as the Vulkan path's (a defect that moves both passes alike, such as
// culling the wrong faces, passes the first check but not the second); a wrong reference is
// caught through each; the runners' errors are one line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <map>
#include <string>

#include "glrun/gl_compute.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"
#include "preview/draw_passes.hpp"
#include "preview/preview.hpp"
#include "preview/preview_scene.hpp"
#include "support/cli_support.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "webgl/webgl_draw.hpp"

using namespace mb;

namespace preview_targets_test {

constexpr uint32_t kTestSize = 56;
constexpr uint32_t kTestCubeSize = 32, kTestLutSize = 32;

harness::VulkanHarness& device() {
  static harness::VulkanHarness gpu(harness::testDeviceOptions());
  return gpu;
}

const preview::PreviewEnvironment& studio() {
  static const preview::PreviewEnvironment env =
      preview::prepareEnvironment(device(), test::shippedLibrary(), "studio", kTestCubeSize, kTestLutSize);
  return env;
}

preview::PreviewOptions options(Target target, std::vector<LightType> lights = {LightType::Dir, LightType::Point}) {
  preview::PreviewOptions o;
  o.size = kTestSize;
  o.lights = std::move(lights);
  o.target = target;
  return o;
}

// Where the preview's camera (preview_scene.hpp viewProjection, Vulkan clip space) sees world
// point p on the tile: x and y in pixels, row 0 at the top.
std::array<double, 2> pixelOf(const float* p) {
  const auto m = preview::viewProjection();
  double clip[4];
  for (int r = 0; r < 4; ++r) clip[r] = m[0 * 4 + r] * p[0] + m[1 * 4 + r] * p[1] + m[2 * 4 + r] * p[2] + m[3 * 4 + r];
  return {(clip[0] / clip[3] + 1) / 2 * kTestSize, (clip[1] / clip[3] + 1) / 2 * kTestSize};
}

// The same scene: where both cover a pixel, the attributes pass of each language shaded a point
// that projects to the same place, and every shaded point faces the camera.
// - Projection: a rasterizer evaluates the attributes at the pixel centre within the triangle it
//   snapped to its sub-pixel grid, so the shaded point projects to the centre moved by at most
//   the vertices' snapping, sqrt(2) 2^-bits pixels; Vulkan and OpenGL ES 3.0 both require at
//   least 4 sub-pixel bits (subPixelPrecisionBits, SUBPIXEL_BITS). Two devices: twice that, plus
//   1e-3 pixel for the fp32 interpolation.
// - Facing: the unit sphere seen from distance d shows the cap z >= 1/d; the tessellation's flat
//   triangles lie inside the sphere by less than 1e-3 there.
// Culling the front faces (the far hemisphere shaded at the same pixels), a flipped row order or a
// shifted viewport fails one of them, while the reference, which reads the same attributes as the
// picture, would agree with the wrong picture.
void checkSameScene(const preview::PreviewResult& other, const preview::PreviewResult& vulkan) {
  REQUIRE(other.covered.size() == vulkan.covered.size());
  const double allowedPixels = 2 * std::sqrt(2.0) / 16 + 1e-3;
  const double capZ = 1 / preview::kCameraDistance - 1e-3;
  size_t coverageDiffers = 0, moved = 0, facingAway = 0;
  double largest = 0;
  for (size_t p = 0; p < other.covered.size(); ++p) {
    if (other.covered[p] != vulkan.covered[p]) {
      ++coverageDiffers;
      continue;
    }
    if (!other.covered[p]) continue;
    const float* a = &other.position[p * 3];
    const float* b = &vulkan.position[p * 3];
    const auto pa = pixelOf(a), pb = pixelOf(b);
    const double d = std::hypot(pa[0] - pb[0], pa[1] - pb[1]);
    largest = std::max(largest, d);
    if (d > allowedPixels) ++moved;
    if (a[2] < capZ || b[2] < capZ) ++facingAway;
  }
  INFO("pixels covered in one picture only: " << coverageDiffers << "; shading another point: " << moved << " (largest "
                                              << largest << " px, allowed " << allowedPixels
                                              << "); facing away: " << facingAway);
  // Rasterizers may break ties on the silhouette differently: a few edge pixels, never the sphere.
  CHECK(coverageDiffers <= other.coveredPixels / 100);
  CHECK(moved == 0);
  CHECK(facingAway == 0);
}

void checkTarget(Target target, const std::string& material, std::vector<LightType> lights,
                 const std::string& deviceWord) {
  const MaterialDesc m = test::shippedMaterial(material);
  const preview::PreviewResult r = preview::renderPreview(preview_targets_test::device(), test::shippedLibrary(), m,
                                                          options(target, lights), studio());
  INFO(material << " " << targetName(target) << " on " << r.device << ": max error/tolerance " << r.maxErrorRatio
                << ", " << r.failures << " outside");
  CHECK(r.device.find(deviceWord) != std::string::npos);
  CHECK(r.coveredPixels > 2000);
  CHECK(r.passed());
  const preview::PreviewResult vulkan = preview::renderPreview(preview_targets_test::device(), test::shippedLibrary(),
                                                               m, options(Target::Spirv, lights), studio());
  checkSameScene(r, vulkan);
}

}  // namespace preview_targets_test

using namespace preview_targets_test;

TEST_CASE("preview draws in every language it offers", "[preview]") {
  CHECK(targetNames(preview::previewTargets()) ==
        std::vector<std::string>{"spirv", "glsl450", "essl310", "hlsl", "webgl2"});
}

TEST_CASE("GLSL 450 and ESSL 3.10 previews drawn by Mesa's GL match the reference and the Vulkan picture",
          "[preview][gl][vulkan]") {
  for (Target target : {Target::Glsl450, Target::Essl310}) {
    checkTarget(target, "filament_plastic", {LightType::Dir, LightType::Point}, "llvmpipe");
    checkTarget(target, "velvet_green", {LightType::Dir, LightType::Spot}, "llvmpipe");
    checkTarget(target, "clearcoat_metal", {LightType::Dir}, "llvmpipe");
    // The LTC table (rect, disk) and the sheen's lobe: a second 2D texture, read by name.
    checkTarget(target, "satin_sheen", {LightType::Rect, LightType::Disk}, "llvmpipe");
  }
}

TEST_CASE("HLSL previews, compiled back by glslang and drawn with Vulkan, match the reference and the SPIR-V picture",
          "[preview][vulkan]") {
  checkTarget(Target::Hlsl, "filament_plastic", {LightType::Dir, LightType::Point}, "llvmpipe");
  checkTarget(Target::Hlsl, "velvet_green", {LightType::Dir, LightType::Spot}, "llvmpipe");
  checkTarget(Target::Hlsl, "satin_sheen", {LightType::Rect, LightType::Disk}, "llvmpipe");
  const MaterialDesc m = test::shippedMaterial("ue4_metal");
  preview::PreviewOptions o = options(Target::Hlsl);
  o.referenceOverrides["roughness"] = {m.param("roughness")->value[0] + 0.01};
  CHECK_FALSE(preview::renderPreview(preview_targets_test::device(), test::shippedLibrary(), m, o, studio()).passed());
}

TEST_CASE("a wrong reference is caught through the GL targets", "[preview][gl][vulkan]") {
  const MaterialDesc m = test::shippedMaterial("ue4_metal");
  for (Target target : {Target::Glsl450, Target::Essl310}) {
    preview::PreviewOptions o = options(target);
    o.referenceOverrides["roughness"] = {m.param("roughness")->value[0] + 0.01};
    const preview::PreviewResult r =
        preview::renderPreview(preview_targets_test::device(), test::shippedLibrary(), m, o, studio());
    CHECK(r.failures > 0);
    CHECK_FALSE(r.passed());
  }
}

// Hidden: CTest runs every [chromium] test once under the label `chromium` (tests/CMakeLists.txt).
TEST_CASE("WebGL 2.0 previews in headless Chromium match the reference and the Vulkan picture",
          "[.][chromium][webgl][preview][vulkan]") {
  const std::string word = "WebGL 2.0";
  checkTarget(Target::Webgl2, "filament_plastic", {LightType::Dir, LightType::Point}, word);
  checkTarget(Target::Webgl2, "velvet_green", {LightType::Dir, LightType::Spot}, word);
  checkTarget(Target::Webgl2, "satin_sheen", {LightType::Rect, LightType::Disk}, word);

  SECTION("a wrong reference is caught") {
    const MaterialDesc m = test::shippedMaterial("ue4_metal");
    preview::PreviewOptions o = options(Target::Webgl2);
    o.referenceOverrides["roughness"] = {m.param("roughness")->value[0] + 0.01};
    const preview::PreviewResult r =
        preview::renderPreview(preview_targets_test::device(), test::shippedLibrary(), m, o, studio());
    CHECK(r.failures > 0);
    CHECK_FALSE(r.passed());
  }
  SECTION("a shader the browser rejects is one line naming the stage") {
    gl::DrawJob job;
    job.width = job.height = 4;
    job.vertexSource = "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n";
    job.fragmentSource = "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = undefined; }\n";
    try {
      webgl::drawInBrowser({job});
      FAIL("no error");
    } catch (const webgl::WebglError& e) {
      const std::string what = e.what();
      CHECK(what.find("fragment shader") != std::string::npos);
      CHECK(what.find("undefined") != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
    }
  }
  SECTION("the command line: --target webgl2 draws in Chromium and says so") {
    const auto dir = test::freshTempDir("preview-targets", "webgl2-cli");
    auto r = test::runCli("preview " + test::materialPath("filament_plastic.json") +
                          " --target webgl2 --size 48 --environment-mode none -o " + (dir / "out").string());
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(r.output.find("drawn by ANGLE") != std::string::npos);
  }
}

TEST_CASE("preview --target refuses an unknown language and a missing chromium", "[preview][vulkan]") {
  const auto dir = test::freshTempDir("preview-targets", "errors");
  auto bad = test::runCli("preview " + test::materialPath("filament_plastic.json") + " --target msl -o " +
                          (dir / "a").string());
  CHECK(bad.exitCode == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "a"));
  auto missing = test::runCli(
      "preview " + test::materialPath("filament_plastic.json") + " --target webgl2 -o " + (dir / "b").string(),
      "MATBRICKS_CHROMIUM=" + (dir / "no-such-chromium").string());
  INFO(missing.output);
  CHECK(missing.exitCode == 4);
  CHECK(missing.output.find("MATBRICKS_CHROMIUM=") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "b"));
}

namespace preview_targets_test {

// The sweep of one language: every shipped material with all its lights together in every
// environment mode its model supports under both environments, and with each light alone under
// the studio in the first of those modes; each picture against the reference and the Vulkan
// picture's geometry. (Each light alone in every mode is validate's sweep; here every draw pays
// the driver's compile of a whole fragment shader.)
void sweepLanguage(Target target, const std::string& deviceWord) {
  const ShaderLibrary& lib = test::shippedLibrary();
  static const preview::PreviewEnvironment sky =
      preview::prepareEnvironment(device(), lib, "sky", kTestCubeSize, kTestLutSize);
  auto check = [&](const MaterialDesc& m, std::vector<LightType> lights, EnvironmentMode mode,
                   const preview::PreviewEnvironment& env) {
    preview::PreviewOptions o = options(target, std::move(lights));
    o.environmentMode = mode;
    const preview::PreviewResult r = preview::renderPreview(device(), lib, m, o, env);
    INFO(r.key << " under " << env.maps.name << " on " << r.device << ": max error/tolerance " << r.maxErrorRatio);
    CHECK(r.device.find(deviceWord) != std::string::npos);
    CHECK(r.passed());
    o.target = Target::Spirv;
    checkSameScene(r, preview::renderPreview(device(), lib, m, o, env));
  };
  for (const auto& file : test::exampleMaterialFiles()) {
    const MaterialDesc m = loadMaterialJson(file, lib);
    const std::vector<Permutation> perms = validationPermutationsFor(m, lib);
    for (const Permutation& perm : perms)
      for (const preview::PreviewEnvironment* env : {&studio(), &sky}) check(m, perm.lights, perm.environment, *env);
    for (LightType light : perms.front().lights) check(m, {light}, perms.front().environment, studio());
  }
}

}  // namespace preview_targets_test

// Hidden, one per language, so that CTest runs them side by side (preview_sweep_*, label sweep).
TEST_CASE("every shipped material, light set and environment previews in GLSL 450", "[.preview-sweep-glsl450]") {
  sweepLanguage(Target::Glsl450, "llvmpipe");
}
TEST_CASE("every shipped material, light set and environment previews in ESSL 3.10", "[.preview-sweep-essl310]") {
  sweepLanguage(Target::Essl310, "llvmpipe");
}
TEST_CASE("every shipped material, light set and environment previews in HLSL", "[.preview-sweep-hlsl]") {
  sweepLanguage(Target::Hlsl, "llvmpipe");
}
TEST_CASE("every shipped material, light set and environment previews in WebGL 2.0", "[.preview-sweep-webgl2]") {
  sweepLanguage(Target::Webgl2, "WebGL 2.0");
}
