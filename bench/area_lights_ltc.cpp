#include "area_lights_ltc.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

#include "brick_call.hpp"
#include "directions.hpp"
#include "common/area_light_truth.hpp"
#include "common/ltc_reference.hpp"
#include "ratio_summary.hpp"

namespace mb::bench {
namespace {

using namespace mb::ref;
using nlohmann::json;

const ref::ltc::Mat3 kIdentity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

// The fan quadrature of the lobe itself over the horizon-clipped polygon, without the LTC: what
// the control variate adds is measured against it.
double quadratureAlone(const ref::ltc::ViewFrame& fr, const Vec3& v, double alpha, const std::vector<Vec3>& polygon) {
  std::vector<Vec3> local;
  for (const Vec3& w : polygon) local.push_back(fr.toLocal(w));
  const Vec3 vl = fr.toLocal(v);
  return ref::ltc::fanQuadrature(ref::ltc::clipToHalfSpace(local, Vec3{0, 0, 1}),
                                 [&](const Vec3& l) { return ref::ltc::ggxLobeLocal(vl, alpha, l); });
}

// The control variate as the bricks had it before: the residual's fan quadrature (unsplit) in
// the light's own directions instead of the LTC's space (common/ltc_reference.hpp says why).
double residualInLightDirections(const mb::ltc::TableSample& s, double alpha, const ref::ltc::ViewFrame& fr,
                                 const Vec3& v, const std::vector<Vec3>& polygon) {
  std::vector<Vec3> local;
  for (const Vec3& w : polygon) local.push_back(fr.toLocal(w));
  local = ref::ltc::clipToHalfSpace(local, Vec3{0, 0, 1});
  const Vec3 vl = fr.toLocal(v);
  double residual = ref::ltc::fanQuadrature(local, [&](const Vec3& l) {
    return ref::ltc::ggxLobeLocal(vl, alpha, l) - s.norm * ref::ltc::density(s.minv, l);
  });
  return std::max(s.norm * ref::ltc::polygonIntegral(s.minv, fr, polygon) + residual, 0.0);
}

// The standard model's sphere light by its default bricks (standard.json, standard_lights.glsl):
// D at the point brick's direction times the normalization brick, V at the centre, both times
// the horizon wrap brick; specular and diffuse as integrals over the light's radiance, so that they
// compare with the brute force (E = L pi sin^2 a).
struct RepresentativeSphere {
  double specular = 0, diffuse = 0;
};
RepresentativeSphere representativeSphere(const SphereLightBricks& b, const Geometry& gc, double alpha, double sinA) {
  RepresentativeSphere out;
  std::vector<double> args = pack(gc);
  args.push_back(sinA);
  double wrap = callBrick(b.wrap, args)[0];
  double E = kPi * sinA * sinA;
  out.diffuse = wrap * E;
  std::vector<double> p = pack(gc);
  append(p, gc.l);
  append(p, gc.l);
  p.push_back(sinA);
  std::vector<double> l = callBrick(b.point, p);
  Geometry gD = makeGeometry(gc.n, gc.v, Vec3{l[0], l[1], l[2]});
  if (!(gD.NoH > 1e-4)) return out;  // mb_facing
  std::vector<double> k = pack(gc);
  k.insert(k.end(), {alpha, sinA});
  double norm = callBrick(b.normalization, k)[0];
  out.specular =
      lights::ggxD(gD.NoH, alpha) * norm * smithGgxCorrelatedV(std::max(gc.NoV, kMinNoV), gc.NoL, alpha) * wrap * E;
  return out;
}

}  // namespace

SphereLightBricks standardSphereLight(const ShaderLibrary& lib) {
  const ShadingModel* standard = lib.findModel("standard");
  if (!standard) throw std::runtime_error("the library has no standard model");
  auto role = [&](const std::string& name) {
    for (const ModelRole& r : standard->roles)
      if (r.role == name && !r.defaultBrick.empty()) return r.defaultBrick;
    throw std::runtime_error("the standard model has no default brick for role " + name);
  };
  return {role("sphere_light_point"), role("sphere_energy_normalization"), role("sphere_horizon_wrap")};
}

json measureLtcAreaLights(const mb::ltc::Table& table, const SphereLightBricks& representative, int sphereSamples,
                          int tubeSamples, int planarSamples, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Vec3 n{0, 0, 1};
  std::map<std::string, Summary> sphere, tube;
  for (int i = 0; i < sphereSamples; ++i) {
    double roughness = 0.05 + 0.95 * U(rng), alpha = roughness * roughness;
    double sinA = std::exp(std::log(0.01) + (std::log(0.5) - std::log(0.01)) * U(rng));
    double NoV = 0.05 + 0.95 * U(rng);
    Vec3 v = unitFromAngles(NoV, 2 * kPi * U(rng));
    Vec3 r = n * (2 * NoV) - v;
    bool nearMirror = i % 2;
    Vec3 c = nearMirror ? around(r, (alpha + std::asin(sinA)) * 2.0 * U(rng), 2 * kPi * U(rng))
                        : unitFromAngles(-sinA + (1 + sinA) * U(rng), 2 * kPi * U(rng));
    if (dot(n, c) <= -sinA + 1e-3) continue;  // no part above the horizon
    Geometry gc = makeGeometry(n, v, c);
    char where[160];
    std::snprintf(where, sizeof where, "r %.4g, sin a %.4g, n.v %.4g, n.c %.4g, angle(r, c) %.4g rad", roughness, sinA,
                  NoV, dot(n, c), std::acos(std::clamp(dot(normalize(r), c), -1.0, 1.0)));
    arealights::LobeIntegrals truth = arealights::sphereLobe(gc, alpha, sinA, 32);
    mb::ltc::TableSample s = mb::ltc::sampleBilinear(table, roughness, NoV);
    ref::ltc::ViewFrame fr = ref::ltc::viewFrame(n, v);
    std::vector<Vec3> polygon = ref::ltc::spherePolygon(c, sinA, n);
    RepresentativeSphere rep = representativeSphere(representative, gc, alpha, sinA);
    if (truth.diffuse > 1e-12) {
      sphere["diffuse: LTC, 8-gon"].add(kPi * ref::ltc::polygonIntegral(kIdentity, fr, polygon) / truth.diffuse, where);
      sphere["diffuse: representative point (" + representative.wrap + ")"].add(rep.diffuse / truth.diffuse, where);
    }
    if (!(truth.specular > 1e-6 * kPi * sinA * sinA)) continue;
    double ltcSpec = s.norm * ref::ltc::polygonIntegral(s.minv, fr, polygon);
    sphere["specular: LTC, 8-gon"].add(ltcSpec / truth.specular, where);
    if (nearMirror) sphere["specular: LTC, 8-gon, lights near the mirror ray"].add(ltcSpec / truth.specular, where);
    double exactCap = lights::capIntegral(
        gc, alpha, sinA, [&](const Vec3& l) { return l.z > 0.0 ? ref::ltc::density(s.minv, fr.toLocal(l)) : 0.0; }, 32);
    sphere["specular: LTC, exact cap (no polygon)"].add(s.norm * exactCap / truth.specular, where);
    sphere["specular: representative point (" + representative.point + " + " + representative.normalization + ")"].add(
        rep.specular / truth.specular, where);
    double cv = ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, polygon);
    sphere["specular: LTC + residual quadrature (sphere_ltc_cv)"].add(cv / truth.specular, where);
    if (nearMirror)
      sphere["specular: LTC + residual quadrature, lights near the mirror ray"].add(cv / truth.specular, where);
    sphere["specular: LTC + residual in the light's directions (the bricks before)"].add(
        residualInLightDirections(s, alpha, fr, v, polygon) / truth.specular, where);
    sphere["specular: a fan quadrature of the lobe alone (no LTC)"].add(
        quadratureAlone(fr, v, alpha, polygon) / truth.specular, where);
  }
  for (int i = 0; i < tubeSamples; ++i) {
    double roughness = 0.05 + 0.95 * U(rng), alpha = roughness * roughness;
    double NoV = 0.05 + 0.95 * U(rng);
    Vec3 v = unitFromAngles(NoV, 2 * kPi * U(rng));
    Vec3 r = n * (2 * NoV) - v;
    Vec3 c = i % 2 ? around(r, 0.5 * U(rng), 2 * kPi * U(rng)) : unitFromAngles(-0.2 + 1.2 * U(rng), 2 * kPi * U(rng));
    Vec3 axis = normalize(Vec3{U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5});
    double halfLength = 0.05 + 1.5 * U(rng), R = std::exp(std::log(0.005) + (std::log(0.2) - std::log(0.005)) * U(rng));
    Vec3 L0 = c - axis * halfLength, L1 = c + axis * halfLength;
    // The shading point inside the capsule (a surface inside the light) means nothing.
    double t = std::clamp(-dot(L0, L1 - L0) / dot(L1 - L0, L1 - L0), 0.0, 1.0);
    if (length(L0 + (L1 - L0) * t) <= R) continue;
    if (dot(n, L0) < -R && dot(n, L1) < -R) continue;  // no part above the horizon
    Geometry gv = makeGeometry(n, v, n);
    char where[200];
    std::snprintf(where, sizeof where, "r %.4g, n.v %.4g, length %.4g, radius %.4g, n.L0 %.3g, n.L1 %.3g", roughness,
                  NoV, 2 * halfLength, R, dot(n, L0), dot(n, L1));
    arealights::LobeIntegrals truth = arealights::tubeLobe(gv, alpha, L0, L1, R);
    if (!(truth.diffuse > 0.0)) continue;
    mb::ltc::TableSample s = mb::ltc::sampleBilinear(table, roughness, NoV);
    ref::ltc::ViewFrame fr = ref::ltc::viewFrame(n, v);
    std::vector<Vec3> polygon = ref::ltc::tubePolygon(L0, L1, R, n);
    double diffuse = kPi * ref::ltc::polygonIntegral(kIdentity, fr, polygon);
    tube["diffuse: LTC, capsule polygon"].add(diffuse / truth.diffuse, where);
    if (!(truth.specular > 1e-9 * truth.diffuse)) continue;
    double spec = s.norm * ref::ltc::polygonIntegral(s.minv, fr, polygon);
    tube["specular: LTC, capsule polygon"].add(spec / truth.specular, where);
    if (i % 2) tube["specular: LTC, capsule polygon, lights near the mirror ray"].add(spec / truth.specular, where);
    double cv = ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, polygon);
    // The residual's quadrature with each fan triangle unsplit and split twice (the bricks split it
    // once: a quarter and 4x their lobe evaluations): how much of tube_ltc_cv's error is the
    // quadrature's.
    for (int levels : {0, 2})
      tube[std::string("specular: LTC + residual, fan triangles ") + (levels ? "split twice" : "unsplit")].add(
          ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, polygon, levels) / truth.specular, where);
    // The capsule with the 8-gon caps it had before (the sides' width 0.948-1.026 of the circle's).
    std::vector<Vec3> polygon8 = ref::ltc::tubePolygon(L0, L1, R, n, 8);
    tube["diffuse: LTC, capsule polygon of 8-gon caps"].add(
        kPi * ref::ltc::polygonIntegral(kIdentity, fr, polygon8) / truth.diffuse, where);
    tube["specular: LTC + residual, capsule polygon of 8-gon caps"].add(
        ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, polygon8) / truth.specular, where);
    tube["specular: LTC + residual quadrature (tube_ltc_cv)"].add(cv / truth.specular, where);
    if (i % 2) tube["specular: LTC + residual quadrature, lights near the mirror ray"].add(cv / truth.specular, where);
    tube["specular: LTC + residual in the light's directions (the bricks before)"].add(
        residualInLightDirections(s, alpha, fr, v, polygon) / truth.specular, where);
    tube["specular: a fan quadrature of the lobe alone (no LTC)"].add(
        quadratureAlone(fr, v, alpha, polygon) / truth.specular, where);
    if (diffuse > 0.0)
      tube["specular over diffuse: LTC, capsule polygon"].add((spec / diffuse) / (truth.specular / truth.diffuse),
                                                              where);
  }
  // Rectangles and disks: the plain LTC (rect_ltc_polygon, disk_ltc_polygon) and the LTC with the
  // residual's quadrature the standard model composes (rect_ltc_cv, disk_ltc_cv), against
  // the lobe integrated adaptively over the light (the disk: over its area-matched 256-gon,
  // which is the ellipse to ~1e-4 of its irradiance). Sizes: half-edges 0.01 to 0.5 at distance
  // 1 (log-uniform), tilted up to 60 degrees from facing the point.
  // Grazing views (n.v 0.001-0.05, a third as many configurations) are kept apart: the table's
  // fit is poorest there, and the rows above are the bound's region.
  std::map<std::string, Summary> planar[2];
  Summary planarConvergence;
  const int grazingSamples = planarSamples / 3;
  for (int i = 0; i < planarSamples + grazingSamples; ++i) {
    const bool grazing = i >= planarSamples;
    const bool disk = i % 4 >= 2;
    double roughness = 0.05 + 0.95 * U(rng), alpha = roughness * roughness;
    double NoV = grazing ? 0.001 + 0.049 * U(rng) : 0.05 + 0.95 * U(rng);
    Vec3 v = unitFromAngles(NoV, 2 * kPi * U(rng));
    Vec3 r = n * (2 * NoV) - v;
    bool nearMirror = i % 2;
    auto size = [&] { return std::exp(std::log(0.01) + (std::log(0.5) - std::log(0.01)) * U(rng)); };
    double hx = size(), hy = size();
    Vec3 c = nearMirror ? around(r, (alpha + std::max(hx, hy)) * 2.0 * U(rng), 2 * kPi * U(rng))
                        : unitFromAngles(-0.3 + 1.3 * U(rng), 2 * kPi * U(rng));
    ref::ltc::PlanarLight l = ref::ltc::facingPlanarLight(c, hx, hy, 2 * kPi * U(rng), (2 * U(rng) - 1) * kPi / 3);
    std::vector<Vec3> polygon = disk ? ref::ltc::diskPolygon(l.c, l.ex, l.ey) : ref::ltc::rectPolygon(l.c, l.ex, l.ey);
    std::vector<Vec3> exact = disk ? ref::ltc::diskPolygon(l.c, l.ex, l.ey, 256) : polygon;
    ref::ltc::ViewFrame fr = ref::ltc::viewFrame(n, v);
    std::vector<Vec3> local;
    for (const Vec3& w : exact) local.push_back(fr.toLocal(w));
    local = ref::ltc::clipToHalfSpace(local, Vec3{0, 0, 1});
    if (local.size() < 3) continue;  // no part above the horizon
    const Vec3 vl = fr.toLocal(v);
    char where[200];
    std::snprintf(where, sizeof where, "%s r %.4g, n.v %.4g, half sizes %.3g x %.3g, n.c %.3g, angle(r, c) %.4g rad",
                  disk ? "disk" : "rect", roughness, NoV, hx, hy, dot(n, c),
                  std::acos(std::clamp(dot(normalize(r), c), -1.0, 1.0)));
    std::map<std::string, Summary>& m = planar[disk ? 1 : 0];
    const double diffuseTruth = kPi * ref::ltc::clampedCosinePolygon(local);
    if (!grazing && diffuseTruth > 1e-12)
      m["diffuse: LTC (M = I)"].add(kPi * ref::ltc::polygonIntegral(kIdentity, fr, polygon) / diffuseTruth, where);
    mb::ltc::TableSample s = mb::ltc::sampleBilinear(table, roughness, NoV);
    const double ltcSpec = s.norm * ref::ltc::polygonIntegral(s.minv, fr, polygon);
    const double scale = std::max(ltcSpec, 1e-3 * diffuseTruth);
    const double truth = ref::ltc::lobeIntegralAdaptive(local, vl, alpha, 1e-6 * scale);
    if (!(truth > 1e-6 * diffuseTruth)) continue;
    const std::string shape = disk ? "disk_ltc_polygon" : "rect_ltc_polygon";
    const std::string cvShape = disk ? "disk_ltc_cv" : "rect_ltc_cv";
    const double cv = ref::ltc::polygonSpecularWithResidual(s.minv, s.norm, alpha, fr, v, polygon);
    if (grazing) {
      m["grazing views (n.v 0.001-0.05), specular: LTC (" + shape + ")"].add(ltcSpec / truth, where);
      m["grazing views (n.v 0.001-0.05), specular: LTC + residual quadrature (" + cvShape + ")"].add(cv / truth, where);
      continue;
    }
    if (planarConvergence.ratios.size() < 40)
      planarConvergence.add(ref::ltc::lobeIntegralAdaptive(local, vl, alpha, 1e-7 * scale) / truth, where);
    m["specular: LTC (" + shape + ")"].add(ltcSpec / truth, where);
    if (nearMirror) m["specular: LTC, lights near the mirror ray"].add(ltcSpec / truth, where);
    m["specular: LTC + residual quadrature (" + cvShape + ")"].add(cv / truth, where);
    m["specular: LTC + residual in the light's directions (the bricks before)"].add(
        residualInLightDirections(s, alpha, fr, v, polygon) / truth, where);
  }
  auto rows = [](const std::map<std::string, Summary>& m) {
    json out = json::array();
    for (const auto& [key, summary] : m) {
      json row = summary.toJson();
      row["method"] = key;
      out.push_back(row);
    }
    return out;
  };
  return {{"table", "shaderlib/ltc/ggx.json"},
          {"seed", seed},
          {"sphere", rows(sphere)},
          {"tube", rows(tube)},
          {"rect", rows(planar[0])},
          {"disk", rows(planar[1])},
          {"planar_truth_self_convergence", planarConvergence.toJson()}};
}

std::string ltcMarkdown(const json& section) {
  std::ostringstream md;
  auto num = [](double x) { return threeDigits(x); };
  const std::map<std::string, std::string> titles = {{"sphere", "Sphere, LTC and representative point"},
                                                     {"tube", "Tube, LTC and representative point"},
                                                     {"rect", "Rectangle, LTC"},
                                                     {"disk", "Disk, LTC"}};
  for (const char* shape : {"sphere", "tube", "rect", "disk"}) {
    if (!section.contains(shape)) continue;
    md << "**" << titles.at(shape) << "** (ratio to the brute-force integral; partly below the horizon included)\n\n"
       << "| method | samples | median ratio | median \\|ratio − 1\\| | 95 % \\|ratio − 1\\| | min | max |\n"
       << "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& r : section.at(shape))
      md << "| " << r.at("method").get<std::string>() << " | " << r.at("samples").get<int>() << " | "
         << num(r.at("ratio_median")) << " | " << num(r.at("rel_error_median")) << " | " << num(r.at("rel_error_p95"))
         << " | " << num(r.at("ratio_min")) << " | " << num(r.at("ratio_max")) << " |\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace mb::bench
