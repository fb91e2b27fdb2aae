// Area lights against a brute-force ground truth (issue 14, item 5): every representative-point
// and normalization brick of the sphere and tube lights, composed as the standard model composes
// them (docs/models/lights.md), against the GGX lobe and the Lambert cosine integrated over the
// light's solid angle in double (shaderlib/common/area_light_truth.hpp). The bricks are their
// double references (the approximation is measured, not fp32; their fp32 error is validate's
// business), and each composition's cost is the sum of its bricks' ns/eval and SPIR-V
// instructions measured by `matbricks bench` (bench.json, the argument).
//
// Sphere (whole cap above the horizon, so the horizon wrap is exactly n.c), per composition:
//   ratio = D(l_rep) k V(c) (n.c) / ((1 / (pi sin^2 a)) Int_cap D V (n.l)+ dw)
// Tube (whole capsule above the horizon): the intensity convention of a capsule cancels in the
// ratio of specular to diffuse, which the model forms from the same E:
//   ratio = pi D(l_rep) k V(w) / (pi Int D V (n.l)+ dw / Int (n.l)+ dw)
// Diffuse: each horizon-wrap brick against (1 / (pi sin^2 a)) Int_cap (n.l)+ dw, crossing the
// horizon too.
// Then linearly transformed cosines beside the representative point (area_lights_ltc.hpp).
// Usage: mb_bench_area_lights bench.json [sphere samples] [tube samples] [seed] [tables.md] > area_lights.json
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "area_lights_ltc.hpp"
#include "area_lights_sheen.hpp"
#include "brick_call.hpp"
#include "directions.hpp"
#include "common/area_light_truth.hpp"
#include "ratio_summary.hpp"
#include "common/reference.hpp"

using namespace mb::ref;
using nlohmann::json;
using mb::bench::append;
using mb::bench::around;
using mb::bench::unitFromAngles;
using mb::bench::callBrick;
using mb::bench::pack;
using mb::bench::Summary;

namespace {

// A tube_light_point brick's representative direction (a zero-length segment: the sphere's).
Vec3 representative(const std::string& id, const Geometry& g, const Vec3& L0, const Vec3& L1, double radius) {
  std::vector<double> args = pack(g);
  append(args, L0);
  append(args, L1);
  args.push_back(radius);
  std::vector<double> l = callBrick(id, args);
  return {l[0], l[1], l[2]};
}
// A brick of signature (Geometry g, float alpha, float sinAlpha).
double sphereBrick(const std::string& id, const Geometry& g, double alpha, double sinAlpha) {
  std::vector<double> args = pack(g);
  args.insert(args.end(), {alpha, sinAlpha});
  return callBrick(id, args)[0];
}

struct Cost {
  double ns = 0;
  double instructions = 0;
};
std::map<std::string, Cost> readCosts(const std::string& benchJson) {
  std::map<std::string, Cost> costs;
  std::ifstream in(benchJson);
  if (!in) return costs;
  json j = json::parse(in);
  // Only resolved costs: a cost below resolution has "ns_per_eval": null (compiler/bench_engine/cost.hpp).
  for (const auto& g : j.at("groups"))
    for (const auto& it : g.at("items"))
      if (it.at("ns_per_eval").is_number())
        costs[it.at("id").get<std::string>()] = {it.at("ns_per_eval").get<double>(),
                                                 it.at("spirv_instructions").get<double>()};
  return costs;
}

const double kPiD = std::numbers::pi;

// The tables of docs/models/lights.md ("Against a brute-force ground truth"): spliced between
// its generated-part markers when the file has them, else the whole file.
void writeMarkdown(const json& out, const std::string& path) {
  std::ostringstream md;
  auto num = [](double x) { return mb::bench::threeDigits(x); };
  auto table = [&](const char* title, const json& rows, const char* what) {
    md << "**" << title << "** (" << what << ")\n\n"
       << "| composition | ns/eval | SPIR-V instructions | samples | median | 5 % | 95 % | min | max | mean \\|ratio − 1\\| |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : rows) {
      bool cost = r.contains("ns_per_eval");
      md << "| `" << r.at("composition").get<std::string>() << "` | "
         << (cost ? num(r.at("ns_per_eval").get<double>()) : "—") << " | "
         << (cost ? num(r.at("spirv_instructions").get<double>()) : "—") << " | " << r.at("samples").get<int>() << " | "
         << num(r.at("ratio_median")) << " | " << num(r.at("ratio_p05")) << " | " << num(r.at("ratio_p95")) << " | "
         << num(r.at("ratio_min")) << " | " << num(r.at("ratio_max")) << " | " << num(r.at("mean_rel_error")) << " |\n";
    }
    md << "\n";
  };
  table("Sphere, specular", out.at("sphere_specular"), "ratio to the brute-force lobe, cap above the horizon");
  table("Sphere, diffuse", out.at("sphere_diffuse"),
        "wrap brick over the exact irradiance ratio, crossing the horizon too");
  table("Tube, specular over diffuse", out.at("tube_specular_over_diffuse"),
        "ratio to the brute-force ratio, capsule above the horizon");
  table("Tube, line normalization forms", out.at("tube_line_normalization_forms"),
        "with tube_point_karis and the sphere factor of norm_tube_karis");
  if (out.contains("ltc")) md << mb::bench::ltcMarkdown(out.at("ltc"));
  if (out.contains("ltc_sheen")) md << mb::bench::ltcSheenMarkdown(out.at("ltc_sheen"));
  const std::string begin = "<!-- begin: generated by mb_bench_area_lights -->\n",
                    end = "<!-- end: generated by mb_bench_area_lights -->";
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  size_t b = text.find(begin), e = text.find(end);
  text = b != std::string::npos && e != std::string::npos && e > b
             ? text.substr(0, b + begin.size()) + md.str() + text.substr(e)
             : md.str();
  std::ofstream(path) << text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s bench.json [sphere samples] [tube samples] [seed]\n", argv[0]);
    return 2;
  }
  std::map<std::string, Cost> costs = readCosts(argv[1]);
  int sphereSamples = argc > 2 ? std::atoi(argv[2]) : 1500;
  int tubeSamples = argc > 3 ? std::atoi(argv[3]) : 600;
  const uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Vec3 n{0, 0, 1};

  // Every brick of each area-light slot, in the library's order: a brick added to a slot joins
  // its table with no change here.
  const mb::ShaderLibrary lib = mb::ShaderLibrary::load(MB_SOURCE_DIR "/shaderlib");
  const std::vector<std::string> points = lib.bricksOfSlot("tube_light_point");
  const std::vector<std::string> sphereNorms = lib.bricksOfSlot("sphere_energy_normalization");
  const std::vector<std::string> maxNoH = lib.bricksOfSlot("sphere_max_noh");
  const std::vector<std::string> wraps = lib.bricksOfSlot("sphere_horizon_wrap");
  const std::vector<std::string> tubeNorms = lib.bricksOfSlot("tube_energy_normalization");
  const std::vector<std::string> sphereDs = lib.bricksOfSlot("sphere_light_d");
  // The line-normalization study below is of Karis 2013's own forms: his representative point.
  const std::string karisPoint = "tube_point_karis";

  std::map<std::string, Summary> sphere, tube, diffuse, tubeLineForms;
  Summary sphereConvergence, tubeConvergence;
  std::map<std::string, std::vector<std::string>> bricksOf;

  // ---- Sphere lights.
  for (int i = 0; i < sphereSamples; ++i) {
    double roughness = 0.1 + 0.9 * U(rng), alpha = roughness * roughness;
    double sinA = std::exp(std::log(0.01) + (std::log(0.5) - std::log(0.01)) * U(rng));
    Vec3 v = unitFromAngles(0.05 + 0.95 * U(rng), 2 * kPiD * U(rng));
    Vec3 r = n * (2 * dot(n, v)) - v;
    // Half the lights near the mirror ray (where the lobe sees them), half anywhere above.
    Vec3 c = i % 2 ? around(r, (alpha + std::asin(sinA)) * 2.0 * U(rng), 2 * kPiD * U(rng))
                   : unitFromAngles(U(rng), 2 * kPiD * U(rng));
    double NoC = dot(n, c);
    Geometry gc = makeGeometry(n, v, c);
    double sinAlpha = sinA;
    char where[160];
    std::snprintf(where, sizeof where, "alpha %.4g, sin a %.4g, n.v %.4g, n.c %.4g, angle(r, c) %.4g rad", alpha, sinA,
                  dot(n, v), NoC, std::acos(std::clamp(dot(r, c), -1.0, 1.0)));
    // The wrap brick's diffuse truth, also across the horizon.
    if (NoC > -sinAlpha) {
      double truthDiffuse = lights::sphereIrradianceOverPoint(gc, sinAlpha);
      if (truthDiffuse > 1e-3) {
        std::vector<double> args = pack(gc);
        args.push_back(sinAlpha);
        for (const auto& w : wraps) {
          diffuse[w].add(callBrick(w, args)[0] / truthDiffuse, where);
          bricksOf[w] = {w};
        }
      }
    }
    if (NoC < sinAlpha + 1e-3) continue;  // the cap crosses the horizon: the wrap's business
    arealights::LobeIntegrals truth = arealights::sphereLobe(gc, alpha, sinAlpha, 32);
    double truthSpec = truth.specular / (kPiD * sinAlpha * sinAlpha);
    if (!(truthSpec > 1e-6)) continue;
    // Self-convergence of the truth (4x the azimuth panels) on the first configurations.
    if (sphereConvergence.ratios.size() < 60)
      sphereConvergence.add(arealights::sphereLobe(gc, alpha, sinAlpha, 128).specular / truth.specular, where);
    double V = smithGgxCorrelatedV(std::max(dot(n, v), kMinNoV), NoC, alpha) * NoC;
    const Vec3 L = c;  // distance 1: the bricks take positions in world units
    // D at a representative point (a direction, or a max-n.h brick's n.h) times each norm.
    auto withNorms = [&](const std::string& point, double D) {
      for (const auto& k : sphereNorms) {
        std::string key = point + " + " + k;
        sphere[key].add(D * sphereBrick(k, gc, alpha, sinAlpha) * V / truthSpec, where);
        bricksOf[key] = {point, k};
      }
    };
    for (const auto& p : points)
      withNorms(p, lights::ggxD(std::max(0.0, lights::nohFor(gc, representative(p, gc, L, L, sinAlpha))), alpha));
    for (const auto& m : maxNoH) {
      std::vector<double> args = pack(gc);
      args.push_back(sinAlpha);
      withNorms(m, lights::ggxD(callBrick(m, args)[0], alpha));
    }
    for (const auto& d : sphereDs) {
      sphere[d].add(sphereBrick(d, gc, alpha, sinAlpha) * V / truthSpec, where);
      bricksOf[d] = {d};
    }
    // The floor of every representative-point method: the exact D averaged over the cap, with V
    // and the cosine taken at the centre.
    sphere["exact D_eff at the centre (no brick)"].add(lights::sphereEffectiveD(gc, alpha, sinAlpha) * V / truthSpec,
                                                       where);
  }

  // ---- Tube lights.
  for (int i = 0; i < tubeSamples; ++i) {
    double roughness = 0.1 + 0.9 * U(rng), alpha = roughness * roughness;
    Vec3 v = unitFromAngles(0.05 + 0.95 * U(rng), 2 * kPiD * U(rng));
    Vec3 r = n * (2 * dot(n, v)) - v;
    Vec3 c = i % 2 ? around(r, 0.5 * U(rng), 2 * kPiD * U(rng)) : unitFromAngles(U(rng), 2 * kPiD * U(rng));
    Vec3 axis = normalize(Vec3{U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5});
    double halfLength = 0.05 + 1.5 * U(rng), R = std::exp(std::log(0.005) + (std::log(0.2) - std::log(0.005)) * U(rng));
    Vec3 L0 = c - axis * halfLength, L1 = c + axis * halfLength;
    if (dot(n, L0) < R + 1e-3 || dot(n, L1) < R + 1e-3) continue;  // the capsule crosses the horizon
    if (length(L0) <= R || length(L1) <= R) continue;
    Geometry gv = makeGeometry(n, v, n);
    char where[200];
    std::snprintf(where, sizeof where, "alpha %.4g, n.v %.4g, length %.4g, radius %.4g, angle(r, centre) %.4g rad",
                  alpha, dot(n, v), 2 * halfLength, R, std::acos(std::clamp(dot(r, normalize(c)), -1.0, 1.0)));
    arealights::LobeIntegrals truth = arealights::tubeLobe(gv, alpha, L0, L1, R);
    if (!(truth.diffuse > 0.0) || !(truth.specular > 1e-9 * truth.diffuse)) continue;
    double truthRatio = kPiD * truth.specular / truth.diffuse;
    // The equivalent point's direction (the bisector of the end directions), V there.
    Vec3 w = normalize(normalize(L0) + normalize(L1));
    Geometry gw = makeGeometry(n, v, w);
    double V = smithGgxCorrelatedV(std::max(dot(n, v), kMinNoV), dot(n, w), alpha);
    for (const auto& p : points) {
      Vec3 l = representative(p, gw, L0, L1, R);
      Geometry gD = makeGeometry(n, v, l);
      double D = lights::ggxD(std::max(0.0, lights::nohFor(gD, l)), alpha);
      for (const auto& k : tubeNorms) {
        std::vector<double> a = pack(gD);
        a.push_back(alpha);
        append(a, L0);
        append(a, L1);
        a.push_back(R);
        std::string key = p + " + " + k;
        tube[key].add(kPiD * D * callBrick(k, a)[0] * V / truthRatio, where);
        bricksOf[key] = {p, k};
      }
      if (p != karisPoint) continue;
      // Settling the line's alpha' (Karis 2013 eq. 17 gives only alpha / alpha'; UE4 takes
      // alpha' = saturate(alpha + 0.5 saturate(length / distance))): the widening's constant
      // and the inner saturate, with the sphere factor as norm_tube_karis.
      double dist = 0.5 * length(L0 + L1), lineAngle = length(L1 - L0) / dist;
      double kSphere = alpha / std::min(1.0, alpha + 0.5 * R / dist);
      for (double coef : {0.25, 0.5, 1.0}) {
        for (bool inner : {true, false}) {
          double angle = inner ? std::min(1.0, lineAngle) : lineAngle;
          double kLine = alpha / std::min(1.0, alpha + coef * angle);
          char key[96];
          std::snprintf(key, sizeof key, "alpha' = saturate(alpha + %.2f %s)", coef,
                        inner ? "saturate(length / distance)" : "length / distance");
          tubeLineForms[key].add(kPiD * D * kLine * kSphere * kSphere * V / truthRatio, where);
        }
      }
      // Without the line factor (the sphere's alone), and with it squared (the sphere's power,
      // not the text's one power for a one-dimensional widening), for scale.
      tubeLineForms["no line factor"].add(kPiD * D * kSphere * kSphere * V / truthRatio, where);
      double kLine = alpha / std::min(1.0, alpha + 0.5 * std::min(1.0, lineAngle));
      tubeLineForms["(alpha / alpha')^2, alpha' as UE4's"].add(
          kPiD * D * kLine * kLine * kSphere * kSphere * V / truthRatio, where);
    }
    // The floor of every representative-point method: the exact D averaged over the capsule's
    // solid angle, with V and the cosine taken at the equivalent direction w.
    double Dmean =
        tubes::CapsuleQuadrature(gv, alpha, tubes::CapsuleChart(L0, L1, R), 0.02).integrate([&](const Vec3& l) {
          return lights::ggxD(std::max(0.0, lights::nohFor(gv, l)), alpha);
        });
    tube["exact mean D over the capsule, V and cosine at w (no brick)"].add(
        kPiD * Dmean * V * dot(n, w) / (truthRatio * truth.diffuse), where);
    // Self-convergence of the truth (lobe panels 4x finer) on the first configurations.
    if (tubeConvergence.ratios.size() < 40) {
      arealights::LobeIntegrals fine = arealights::tubeLobe(gv, alpha, L0, L1, R, 0.005);
      tubeConvergence.add((fine.specular / fine.diffuse) / (truth.specular / truth.diffuse), where);
    }
  }

  auto table = [&](const std::map<std::string, Summary>& m) {
    json rows = json::array();
    for (const auto& [key, s] : m) {
      json row = s.toJson();
      row["composition"] = key;
      Cost cost;
      bool known = bricksOf.count(key) > 0;
      if (known)
        for (const auto& b : bricksOf.at(key)) cost.ns += costs[b].ns, cost.instructions += costs[b].instructions;
      if (known) row["ns_per_eval"] = cost.ns, row["spirv_instructions"] = cost.instructions;
      if (known) row["bricks"] = bricksOf.at(key);
      rows.push_back(row);
    }
    return rows;
  };
  json out{{"command", "mb_bench_area_lights"},
           {"cost_from", argv[1]},
           {"sphere_specular", table(sphere)},
           {"sphere_diffuse", table(diffuse)},
           {"tube_specular_over_diffuse", table(tube)},
           {"tube_line_normalization_forms", table(tubeLineForms)},
           {"truth_self_convergence",
            {{"sphere_32_vs_128_azimuth_panels", sphereConvergence.toJson()},
             {"tube_lobe_fraction_0.02_vs_0.005", tubeConvergence.toJson()}}}};
  // LTC against the same truths, on configurations of its own (area_lights_ltc.hpp).
  out["ltc"] = mb::bench::measureLtcAreaLights(mb::ltc::loadTable(MB_SOURCE_DIR "/shaderlib/ltc/ggx.json"),
                                               mb::bench::standardSphereLight(lib), sphereSamples, tubeSamples,
                                               sphereSamples, seed);
  // The sheen's table likewise, a quarter of the sphere samples per shape (area_lights_sheen.hpp).
  out["ltc_sheen"] = mb::bench::measureLtcSheen(mb::ltc::loadTable(MB_SOURCE_DIR "/shaderlib/ltc/charlie.json"),
                                                sphereSamples / 4, seed);
  std::printf("%s\n", out.dump(1).c_str());
  if (argc > 5) writeMarkdown(out, argv[5]);
  return 0;
}
