// Issue 18, item 9: two bricks whose inputs were settled against their sources, evaluated on
// lavapipe (the probe `matbricks eval --brick` runs) and compared with the source's formula
// written out here:
//  - diffuse_fabric_lambert takes alpha: seed 000 calls FabricLambertDiffuse(roughness, ...)
//    and defines "roughness" as alpha = (linear roughness)^2 (its "Roughness or Perceptual
//    Roughness?"), as Unity's Fabric passes roughnessT;
//  - norm_tube_karis saturates the line angle first, as UE4's AreaLightSpecular:
//    LineAngle = saturate(SourceLength / distance), alpha / saturate(alpha + 0.5 LineAngle).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_program.hpp"

using namespace mb;

namespace {

// The brick's GPU value and reference at one input, given by column name.
struct Value {
  double gpu, reference, allowed;
};

Value evalBrick(harness::VulkanHarness& gpu, const std::string& id, const std::map<std::string, double>& value) {
  const Brick* b = test::shippedLibrary().findBrick(id);
  REQUIRE(b);
  ProbeProgram program = buildBrickProbe(test::shippedLibrary(), *b);
  std::vector<float> inputs;
  for (const auto& c : program.shader.layout.columns()) {
    INFO("probe column " << c);
    REQUIRE(value.count(c));
    inputs.push_back(static_cast<float>(value.at(c)));
  }
  ProbeRun run = runProbe(gpu, program, inputs);
  return {run.gpu.at(0), run.reference.at(0),
          program.tolerance.abs + program.tolerance.rel * std::abs(run.reference.at(0)) + run.conditioning.at(0)};
}

std::map<std::string, double> geometry() {
  return {{"n.x", 0},   {"n.y", 0},    {"n.z", 1}, {"v.x", 0.6}, {"v.y", 0},
          {"v.z", 0.8}, {"l.x", -0.6}, {"l.y", 0}, {"l.z", 0.8}};
}

}  // namespace

TEST_CASE("diffuse_fabric_lambert takes alpha, as seed 000 and Unity", "[seed-conventions][gpu][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  // fp32 inputs, as the probe receives them.
  const double r = static_cast<float>(0.8), alpha = static_cast<float>(r * r);
  auto in = geometry();
  in["perceptualRoughness"] = r;
  in["alpha"] = alpha;
  Value v = evalBrick(gpu, "diffuse_fabric_lambert", in);
  const double seed = (1.0 - 0.5 * alpha) / std::numbers::pi;  // lerp(1, 0.5, roughness) / pi
  CHECK(std::abs(v.reference - seed) <= 1e-15);
  CHECK(std::abs(v.gpu - seed) <= v.allowed);
  // With the perceptual roughness the value would be 0.6/pi, not 0.68/pi.
  CHECK(std::abs(v.gpu - (1.0 - 0.5 * r) / std::numbers::pi) > 100 * v.allowed);
}

TEST_CASE("norm_tube_karis saturates the line angle, as UE4", "[seed-conventions][gpu][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  // A tube longer than its distance: |L1 - L0| = 2.89, distance to its centre 1.97.
  // fp32 inputs, as the probe receives them.
  const double alpha = static_cast<float>(0.2), radius = static_cast<float>(0.1);
  const double L0[3] = {1.5, static_cast<float>(0.3), static_cast<float>(0.3)}, L1[3] = {0.5, 3.0, 0.5};
  auto in = geometry();
  in["alpha"] = alpha;
  in["sourceRadius"] = radius;
  for (int k = 0; k < 3; ++k) {
    in[std::string("L0.") + "xyz"[k]] = L0[k];
    in[std::string("L1.") + "xyz"[k]] = L1[k];
  }
  Value v = evalBrick(gpu, "norm_tube_karis", in);
  double len = std::hypot(L1[0] - L0[0], L1[1] - L0[1], L1[2] - L0[2]);
  double dist = std::hypot(L0[0] + L1[0], L0[1] + L1[1], L0[2] + L1[2]) / 2;
  auto saturate = [](double x) { return std::clamp(x, 0.0, 1.0); };
  double line = alpha / saturate(alpha + 0.5 * saturate(len / dist));
  double sphere = std::pow(alpha / saturate(alpha + radius / (2 * dist)), 2);
  CHECK(len / dist > 1.0);
  CHECK(std::abs(v.reference - line * sphere) <= 1e-12 * line * sphere);
  CHECK(std::abs(v.gpu - line * sphere) <= v.allowed);
  // Without the inner saturate the line term would be alpha / saturate(alpha + len / (2 dist)).
  CHECK(std::abs(v.gpu - alpha / saturate(alpha + len / (2 * dist)) * sphere) > 100 * v.allowed);
}
