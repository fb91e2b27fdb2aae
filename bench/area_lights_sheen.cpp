#include "area_lights_sheen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <sstream>

#include "common/ltc_reference.hpp"
#include "directions.hpp"
#include "ratio_summary.hpp"

namespace mb::bench {
namespace {

using namespace mb::ref;
using nlohmann::json;
using ref::ltc::LobeKind;

// One light: its polygon as the bricks build it, and as the ground truth integrates it (the
// circles as 256-gons, which are the circle to ~1e-4 of its area).
struct LightPolygons {
  std::string shape;
  std::vector<Vec3> bricks, exact;
  Vec3 centre;
};

LightPolygons drawLight(int i, const Vec3& n, const Vec3& r, double alpha, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto logUniform = [&](double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * U(rng));
  };
  const bool nearMirror = (i / 4) % 2;
  LightPolygons p;
  switch (i % 4) {
    case 0: {
      p.shape = "sphere";
      const double sinA = logUniform(0.01, 0.5);
      p.centre = nearMirror ? around(r, (alpha + std::asin(sinA)) * 2.0 * U(rng), 2 * kPi * U(rng))
                            : unitFromAngles(-sinA + (1 + sinA) * U(rng), 2 * kPi * U(rng));
      p.bricks = ref::ltc::spherePolygon(p.centre, sinA, n);
      p.exact = ref::ltc::spherePolygon(p.centre, sinA, n, 256);
      break;
    }
    case 1: {
      p.shape = "tube";
      p.centre = nearMirror ? around(r, 0.5 * U(rng), 2 * kPi * U(rng))
                            : unitFromAngles(-0.2 + 1.2 * U(rng), 2 * kPi * U(rng));
      const Vec3 axis = normalize(Vec3{U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5});
      const double halfLength = 0.05 + 1.5 * U(rng), R = logUniform(0.005, 0.2);
      const Vec3 L0 = p.centre - axis * halfLength, L1 = p.centre + axis * halfLength;
      const double t = std::clamp(-dot(L0, L1 - L0) / dot(L1 - L0, L1 - L0), 0.0, 1.0);
      if (length(L0 + (L1 - L0) * t) <= R) return {};  // the shading point inside the light
      p.bricks = ref::ltc::tubePolygon(L0, L1, R, n);
      p.exact = ref::ltc::tubePolygon(L0, L1, R, n, 256);
      break;
    }
    default: {
      const bool disk = i % 4 == 3;
      p.shape = disk ? "disk" : "rect";
      const double hx = logUniform(0.01, 0.5), hy = logUniform(0.01, 0.5);
      p.centre = nearMirror ? around(r, (alpha + std::max(hx, hy)) * 2.0 * U(rng), 2 * kPi * U(rng))
                            : unitFromAngles(-0.3 + 1.3 * U(rng), 2 * kPi * U(rng));
      const ref::ltc::PlanarLight l =
          ref::ltc::facingPlanarLight(p.centre, hx, hy, 2 * kPi * U(rng), (2 * U(rng) - 1) * kPi / 3);
      p.bricks = disk ? ref::ltc::diskPolygon(l.c, l.ex, l.ey) : ref::ltc::rectPolygon(l.c, l.ex, l.ey);
      p.exact = disk ? ref::ltc::diskPolygon(l.c, l.ex, l.ey, 256) : p.bricks;
      break;
    }
  }
  return p;
}

}  // namespace

json measureLtcSheen(const mb::ltc::Table& table, int samples, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Vec3 n{0, 0, 1};
  const ref::ltc::Mat3 identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::map<std::string, std::map<std::string, Summary>> rows;
  int skippedTiny = 0;
  for (int i = 0; i < 4 * samples; ++i) {
    const double roughness = 0.05 + 0.95 * U(rng), alpha = roughness * roughness;
    const double NoV = 0.05 + 0.95 * U(rng);
    const Vec3 v = unitFromAngles(NoV, 2 * kPi * U(rng));
    const LightPolygons light = drawLight(i, n, n * (2 * NoV) - v, alpha, rng);
    if (light.exact.empty()) continue;
    const ref::ltc::ViewFrame fr = ref::ltc::viewFrame(n, v);
    std::vector<Vec3> local;
    for (const Vec3& w : light.exact) local.push_back(fr.toLocal(w));
    local = ref::ltc::clipToHalfSpace(local, Vec3{0, 0, 1});
    if (local.size() < 3) continue;  // no part above the horizon
    const Vec3 vl = fr.toLocal(v);
    const double irradiance = kPi * ref::ltc::clampedCosinePolygon(local);
    const mb::ltc::TableSample s = mb::ltc::sampleBilinear(table, roughness, NoV);
    const double plain = s.norm * ref::ltc::polygonIntegral(s.minv, fr, light.bricks);
    const double truth =
        ref::ltc::lobeIntegralAdaptive(local, vl, alpha, 1e-6 * std::max(plain, 1e-3 * irradiance), LobeKind::Charlie);
    // A sheen below 1e-6 of the light's irradiance (smooth sheens seen head-on reflect almost
    // nothing) is not a ratio worth stating.
    if (!(truth > 1e-6 * irradiance)) {
      ++skippedTiny;
      continue;
    }
    char where[200];
    std::snprintf(where, sizeof where, "%s r %.4g, n.v %.4g, n.c %.3g", light.shape.c_str(), roughness, NoV,
                  dot(n, normalize(light.centre)));
    const double cv = ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, light.bricks,
                                                            ref::ltc::kResidualLevels, LobeKind::Charlie);
    // The model before: the lobe at the centre's direction (cosine 1) times the irradiance of
    // the bricks' polygon.
    const Vec3 c = fr.toLocal(normalize(light.centre));
    const double centreLobe = c.z > 0.0 ? ref::ltc::charlieLobeLocal(vl, alpha, c) / c.z : 0.0;
    const double before = centreLobe * kPi * ref::ltc::polygonIntegral(identity, fr, light.bricks);
    auto& m = rows[light.shape];
    m["sheen: lobe at the centre's direction x irradiance (before)"].add(before / truth, where);
    m["sheen: LTC"].add(plain / truth, where);
    m["sheen: LTC + residual quadrature (*_ltc_sheen_cv)"].add(cv / truth, where);
  }
  json out{{"table", "shaderlib/ltc/charlie.json"}, {"seed", seed}, {"skipped_below_1e-6_of_irradiance", skippedTiny}};
  for (const auto& [shape, m] : rows) {
    json list = json::array();
    for (const auto& [key, summary] : m) {
      json row = summary.toJson();
      row["method"] = key;
      list.push_back(row);
    }
    out[shape] = list;
  }
  return out;
}

std::string ltcSheenMarkdown(const json& section) {
  std::ostringstream md;
  auto num = [](double x) { return threeDigits(x); };
  md << "**Sheen (Charlie D, Ashikhmin V)** (ratio to the brute-force integral; partly below the horizon included; "
     << section.at("skipped_below_1e-6_of_irradiance").get<int>()
     << " lights whose sheen is below 1e-6 of their irradiance left out)\n\n"
     << "| light | method | samples | median ratio | median \\|ratio − 1\\| | 95 % \\|ratio − 1\\| | min | max |\n"
     << "|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const char* shape : {"sphere", "tube", "rect", "disk"}) {
    if (!section.contains(shape)) continue;
    for (const auto& r : section.at(shape))
      md << "| " << shape << " | " << r.at("method").get<std::string>() << " | " << r.at("samples").get<int>() << " | "
         << num(r.at("ratio_median")) << " | " << num(r.at("rel_error_median")) << " | " << num(r.at("rel_error_p95"))
         << " | " << num(r.at("ratio_min")) << " | " << num(r.at("ratio_max")) << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace mb::bench
