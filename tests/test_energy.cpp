// Energy and physics checks (compiler/energy/): white furnace, multiscatter compensation and
// reciprocity, GPU against the double references, on the coarse grid (the fine grid is what
// `matbricks energy` publishes in docs/energy.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "energy/energy_checks.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
using namespace mb::energy;

namespace {

// Double summation of ~10^4 positive terms: relative rounding below 1e-12.
constexpr double kSummationRounding = 1e-12;

std::vector<Lobe> lobesNamed(std::initializer_list<const char*> names) {
  std::vector<Lobe> out;
  for (const Lobe& l : energyLobes(test::shippedLibrary()))
    for (const char* n : names)
      if (l.name == n) out.push_back(l);
  REQUIRE(out.size() == names.size());
  return out;
}

struct Gpu {
  harness::VulkanHarness gpu{harness::testDeviceOptions()};
  ProbeCache probes{test::shippedLibrary()};
  ~Gpu() { CHECK(gpu.validationMessages().empty()); }
};

}  // namespace

TEST_CASE("half-vector maps invert their CDFs and integrate D (n.h) to 1", "[energy]") {
  for (auto kind : {HalfVectorMapKind::Cosine, HalfVectorMapKind::Ggx, HalfVectorMapKind::Beckmann,
                    HalfVectorMapKind::Charlie, HalfVectorMapKind::Ashikhmin}) {
    for (double alpha : {0.002025, 0.09, 0.5, 1.0}) {
      HalfVectorMap map(kind, alpha);
      INFO(mapName(kind) << " alpha " << alpha);
      for (double u : {0.01, 0.3, 0.7, 0.99}) {
        HalfVectorAngle a = map.angleAt(u);
        CHECK(map.cdf(std::atan2(a.sinTheta, a.cosTheta)) == Approx(u).epsilon(1e-9));
      }
      // cdf' = 2 pi pdf sin, checked by a central difference at the median angle.
      HalfVectorAngle m = map.angleAt(0.5);
      double t = std::atan2(m.sinTheta, m.cosTheta), h = 1e-6 * std::min(t, 0.5 * ref::kPi - t);
      double slope = (map.cdf(t + h) - map.cdf(t - h)) / (2 * h);
      CHECK(slope ==
            Approx(2 * ref::kPi * map.density({std::cos(t), std::sin(t)}) * std::sin(t)).epsilon(1e-5).margin(1e-200));
    }
  }
}

TEST_CASE("Lambert albedo is 1 within the quadrature error, on the GPU", "[energy][vulkan]") {
  Gpu g;
  auto lobes = lobesNamed({"diffuse_lambert"});
  auto result = whiteFurnace(g.gpu, g.probes, lobes, EnergyGrid::coarse());
  REQUIRE(result.size() == 1);
  CHECK(result[0].gpuMatchesReference());
  for (const AlbedoCell& c : result[0].cells) {
    INFO("n.v " << c.NoV << " r " << c.perceptualRoughness);
    CHECK(std::abs(c.gpu - 1.0) <= c.bound + 2.0 * c.convergence + kSummationRounding);
    CHECK(std::abs(c.reference - 1.0) <= 2.0 * c.convergence + kSummationRounding);
  }
}

TEST_CASE("GGX with correlated Smith has albedo <= 1 and a known non-conserving lobe is detected", "[energy][vulkan]") {
  Gpu g;
  auto lobes = lobesNamed({"d_ggx * v_smith_ggx_correlated", "diffuse_disney_burley"});
  auto result = whiteFurnace(g.gpu, g.probes, lobes, EnergyGrid::coarse());
  const LobeAlbedo& ggx = result[0];
  CHECK(ggx.gpuMatchesReference());
  CHECK_FALSE(ggx.exceedsOne());
  for (const AlbedoCell& c : ggx.cells) {
    INFO("n.v " << c.NoV << " r " << c.perceptualRoughness);
    CHECK(c.gpu <= 1.0 + c.bound + 2.0 * c.convergence);
    CHECK(c.gpu > 0.3);  // the GGX single-scattering albedo is >= ~0.45 (Kulla & Conty 2017)
  }
  // Burley's diffuse is not normalized: its albedo exceeds 1 at high roughness.
  const LobeAlbedo& burley = result[1];
  CHECK(burley.gpuMatchesReference());
  CHECK(burley.exceedsOne());
}

TEST_CASE("multiscatter-compensated GGX at f0 = 1 has albedo 1 within its derived margin", "[energy][vulkan]") {
  Gpu g;
  auto lobes = lobesNamed({"d_ggx * v_smith_ggx_correlated"});
  EnergyGrid grid = EnergyGrid::coarse();
  auto furnace = whiteFurnace(g.gpu, g.probes, lobes, grid);
  CompensationResult comp = multiscatterCompensation(g.gpu, g.probes, test::shippedLibrary(), furnace[0], grid);
  REQUIRE(comp.cells.size() == grid.NoV.size() * grid.perceptualRoughness.size());
  CHECK(comp.passed());  // every cell within its derived margin (multiscatter.hpp)
  // Stated margin: within 1e-3 of 1 (measured: 5e-6 on this grid, 2.5e-5 on the fine grid,
  // docs/energy.md). The derived margins are looser (up to ~4e-3 here) because the coarse
  // grid's quadrature estimate |A(N) - A(N/2)| is conservative.
  CHECK(comp.maxDeviation() < 1e-3);
  for (const auto& c : comp.cells) CHECK(c.compensation > 1.0);  // E < 1: compensation brightens
}

TEST_CASE("d_ggx * v_smith_ggx_correlated is reciprocal on the GPU; the n.v clamp breaks it below 1e-4",
          "[energy][vulkan]") {
  Gpu g;
  auto lobes = lobesNamed({"d_ggx * v_smith_ggx_correlated", "diffuse_lambert"});
  auto result = reciprocity(g.gpu, g.probes, lobes, EnergyGrid::coarse());
  const ReciprocityResult& ggx = result[0];
  CHECK(ggx.pairs > 0);
  CHECK(ggx.referenceReciprocal());
  CHECK(ggx.passed());
  CHECK(ggx.gpuAsymmetry < 1e-5);
  CHECK_FALSE(ggx.grazingReciprocal());  // V depends on the clamped n.v
  CHECK(result[1].grazingReciprocal());  // Lambert ignores the geometry
  CHECK(result[1].gpuAsymmetry == 0.0);
}

TEST_CASE("matbricks energy --grid coarse --json reports every lobe", "[energy][cli][vulkan]") {
  auto r = test::runCli("energy --grid coarse --json");
  INFO(r.output.substr(0, 2000));
  REQUIRE(r.exitCode == 0);
  auto j = nlohmann::json::parse(r.output);
  CHECK(j["passed"] == true);
  CHECK(j["furnace"].size() == energyLobes(test::shippedLibrary()).size());
  CHECK(j["reciprocity"].size() == j["furnace"].size());
}
