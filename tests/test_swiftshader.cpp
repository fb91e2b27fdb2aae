// A second Vulkan implementation (docs/devices.md): SwiftShader, shipped in Debian's `chromium`
// package (installed by scripts/install-deps.sh), with a shader compiler of its own (Subzero,
// not LLVM) and transcendental functions only as precise as the Vulkan spec requires. fp32
// `validate` of every shipped material through the CLI and `preview` of every shipped material
// under both environments run on it, with the validation layer on, so that code only lavapipe's
// compiler handles fails here. It has no shaderFloat16: fp16 stays on lavapipe. Each test
// asserts the device it ran on, so a run that fell back to lavapipe cannot pass. Hidden tag:
// CTest runs these under the label `swiftshader` (tests/CMakeLists.txt).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "load/material_desc.hpp"
#include "preview/preview.hpp"
#include "support/cli_support.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSwiftShaderIcd = "/usr/lib/chromium/vk_swiftshader_icd.json";
constexpr const char* kSwiftShaderName = "SwiftShader Device (Subzero)";

void requireSwiftShaderIcd() {
  INFO(kSwiftShaderIcd << " is missing: scripts/install-deps.sh installs Debian's `chromium`, which ships it");
  REQUIRE(fs::exists(kSwiftShaderIcd));
}

// The in-process device: the loader sees SwiftShader's ICD only, and the harness is asked for
// it by name (it throws when no device matches).
harness::VulkanHarness& swiftShader() {
  static harness::VulkanHarness gpu = [] {
    ::setenv("VK_ICD_FILENAMES", kSwiftShaderIcd, 1);
    harness::DeviceOptions options = harness::testDeviceOptions();
    options.device = "SwiftShader";
    return harness::VulkanHarness(options);
  }();
  return gpu;
}

// fp32 validate of `files` through the CLI with the validation layer on: every permutation
// passes, on SwiftShader.
void validateOnSwiftShader(const std::vector<std::string>& files) {
  requireSwiftShaderIcd();
  std::string args = "--device SwiftShader --vk-validation validate";
  for (const auto& f : files) args += " " + f;
  const auto r = test::runCli(args, std::string("VK_ICD_FILENAMES=") + kSwiftShaderIcd);
  INFO(r.output);
  CHECK(r.output.find(std::string("device: ") + kSwiftShaderName + "\n") != std::string::npos);
  CHECK(r.output.find(" FAIL\n") == std::string::npos);
  CHECK(r.exitCode == 0);
}

}  // namespace

TEST_CASE("SwiftShader: fp32 validate of every shipped material passes, on SwiftShader",
          "[.][swiftshader][swiftshader-validate][vulkan]") {
  const auto files = test::exampleMaterialFiles();
  REQUIRE(files.size() >= 9);
  validateOnSwiftShader(files);
}

// The default run's part of the sweep above (which CTest runs under the label `sweep`): the
// material whose spot light the first SwiftShader run failed (docs/devices.md), every light
// type and environment mode of its model.
TEST_CASE("SwiftShader: fp32 validate of velvet_green passes, on SwiftShader",
          "[.][swiftshader][swiftshader-validate-one][vulkan]") {
  validateOnSwiftShader({test::materialPath("velvet_green.json")});
}

TEST_CASE("SwiftShader: preview of every shipped material under both environments matches the reference",
          "[.][swiftshader][swiftshader-preview][vulkan]") {
  requireSwiftShaderIcd();
  harness::VulkanHarness& gpu = swiftShader();
  REQUIRE(gpu.deviceName() == kSwiftShaderName);
  // The sizes of tests/test_preview.cpp: ~2000 shaded pixels per sphere, a 32^2 cube and LUT
  // (SwiftShader prefilters the 128^2 default cube for minutes on this VM).
  preview::PreviewOptions o;
  o.size = 56;
  o.lights = {LightType::Dir, LightType::Point};
  const auto files = test::exampleMaterialFiles();
  REQUIRE(files.size() >= 9);
  for (const std::string env : {"studio", "sky"}) {
    const preview::PreviewEnvironment environment =
        preview::prepareEnvironment(gpu, test::shippedLibrary(), env, 32, 32);
    for (const auto& file : files) {
      const MaterialDesc m = loadMaterialJson(file, test::shippedLibrary());
      const preview::PreviewResult r = preview::renderPreview(gpu, test::shippedLibrary(), m, o, environment);
      INFO(m.name << " under " << env << " on " << gpu.deviceName() << ": max error/tolerance " << r.maxErrorRatio
                  << ", " << r.failures << " pixels outside, " << r.nonFinite << " non-finite");
      CHECK(r.coveredPixels > 1000);
      CHECK(r.passed());
    }
  }
  const auto messages = gpu.validationMessages();
  INFO((messages.empty() ? std::string() : messages.front()));
  CHECK(messages.empty());
}
