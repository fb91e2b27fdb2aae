// Light methods on one chart (bench_engine/light_methods.hpp).
#include "bench_engine/light_methods.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <sstream>

#include "bench_engine/report.hpp"
#include "common/area_light_truth.hpp"
#include "common/ltc_reference.hpp"
#include "common/model_reference.hpp"
#include "emit/emitter.hpp"
#include "validate/probe_ltc_table.hpp"
#include "validate/probe_program.hpp"

namespace mb::bench {

namespace {

using ref::Vec3;

// The area lights, in axis order.
const std::vector<LightType> kAreaLights{LightType::Sphere, LightType::Tube, LightType::Rect, LightType::Disk};

// The model's reference input for one permutation's bound roles: the material's inputs, made a
// metal of base colour 1, and the falloff inverse-square, so that a sphere or tube of intensity
// I has the luminance I / A (standard_lights.glsl).
ref::ModelEvalInput referenceInput(const ShaderLibrary& lib, const Permutation& perm,
                                   std::shared_ptr<const ProbeLtcTable> table) {
  ref::ModelEvalInput in;
  for (const auto& [role, id] : boundRoles(lib, perm)) in.bricks[role] = id;
  if (in.bricks.count("light_falloff")) in.bricks["light_falloff"] = "falloff_inverse_square";
  for (const auto& input : lib.findModel(perm.material->model)->inputs)
    if (input.feature.empty()) in.inputs[input.name] = input.defaultValue;
  for (const auto& p : perm.material->params)
    if (!p.user) in.inputs[p.name] = p.value;
  in.inputs["metallic"] = {1.0};
  in.inputs["baseColor"] = {1.0, 1.0, 1.0};
  in.features.insert(perm.material->features.begin(), perm.material->features.end());
  in.fetchLtc = [table](ref::LtcLobe lobe, double NoV, double r) { return table->texel(lobe, NoV, r); };
  return in;
}

class Draws {
 public:
  explicit Draws(uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  Vec3 unit() {
    std::normal_distribution<double> g;
    return ref::normalize(Vec3{g(rng_), g(rng_), g(rng_)});
  }
  // A direction within about `spread` of `axis`. One draw per statement: the order of draws
  // within an expression is the compiler's, and the results must not depend on it.
  Vec3 nearDirection(const Vec3& axis, double spread) {
    const Vec3 offset = unit();
    return ref::normalize(axis + offset * (spread * uniform(0, 1)));
  }

 private:
  std::mt19937_64 rng_;
};

// Sorted |ratio - 1| over `count` lights of `shape`, drawn as mb_bench_area_lights draws them:
// roughness 0.05-1, n.v 0.05-1, half of the lights near the mirror ray, the others anywhere a
// part of them is above the horizon; spheres of sin alpha 0.01-0.5, tubes of radius 0.005-0.2
// and length 0.1-3.1 at unit distance, rectangles and disks of half sizes 0.01-0.5.
std::vector<double> methodErrors(const ref::ModelReferenceFn model, ref::ModelEvalInput in, LightType shape, int count,
                                 uint64_t seed) {
  namespace rl = ref::ltc;
  const Vec3 n{0, 0, 1}, one{1.0, 1.0, 1.0};
  Draws c(seed);
  std::vector<double> errors;
  while (static_cast<int>(errors.size()) < count) {
    const double roughness = c.uniform(0.05, 1.0), alpha = roughness * roughness, NoV = c.uniform(0.05, 1.0);
    const double phi = c.uniform(0.0, 2 * ref::kPi), s = std::sqrt(1 - NoV * NoV);
    const Vec3 v{s * std::cos(phi), s * std::sin(phi), NoV};
    const Vec3 mirror = n * (2 * NoV) - v;
    const bool nearMirror = errors.size() % 2 == 1;
    ref::ModelEvalInput e = in;
    e.frame = {n, v, n, Vec3{1, 0, 0}};
    e.inputs["roughness"] = {roughness};
    double truth = 0, area = 1;  // the model's result over truth / area is the ratio
    if (shape == LightType::Sphere) {
      const double sinA = c.logUniform(0.01, 0.5);
      const Vec3 dir = nearMirror ? c.nearDirection(mirror, alpha + sinA) : c.unit();
      if (dot(n, dir) <= -sinA + 1e-3) continue;  // no part above the horizon
      const ref::arealights::LobeIntegrals t =
          ref::arealights::sphereLobe(ref::makeGeometry(n, v, dir), alpha, sinA, 32);
      if (!(t.specular > 1e-6 * ref::kPi * sinA * sinA)) continue;
      truth = t.specular;
      area = ref::kPi * sinA * sinA;
      e.sphere = ref::SphereLight{dir, sinA, one, 1e6};
    } else if (shape == LightType::Tube) {
      const Vec3 centre = nearMirror ? c.nearDirection(mirror, 0.5) : c.unit();
      const Vec3 axis = c.unit();
      const double halfLength = c.uniform(0.05, 1.55), R = c.logUniform(0.005, 0.2);
      const Vec3 L0 = centre - axis * halfLength, L1 = centre + axis * halfLength, edge = L1 - L0;
      const double t = std::clamp(-dot(L0, edge) / dot(edge, edge), 0.0, 1.0);
      if (length(L0 + edge * t) <= R) continue;  // inside the light
      if (dot(n, L0) < -R && dot(n, L1) < -R) continue;
      const ref::arealights::LobeIntegrals tl = ref::arealights::tubeLobe(ref::makeGeometry(n, v, n), alpha, L0, L1, R);
      if (!(tl.diffuse > 0.0) || !(tl.specular > 1e-9 * tl.diffuse)) continue;
      truth = tl.specular;
      area = ref::kPi * R * R + 2.0 * R * length(edge);
      e.tube = ref::TubeLight{L0, L1, R, one, 1e6};
    } else {
      const bool disk = shape == LightType::Disk;
      const double hx = c.logUniform(0.01, 0.5), hy = c.logUniform(0.01, 0.5);
      const Vec3 centre = nearMirror ? c.nearDirection(mirror, alpha + std::max(hx, hy)) : c.unit();
      const double turn = c.uniform(0, 2 * ref::kPi), tilt = c.uniform(-1, 1) * ref::kPi / 3;
      const rl::PlanarLight light = rl::facingPlanarLight(centre, hx, hy, turn, tilt);
      const rl::PlanarTruth t = rl::planarLobeTruth(n, v, alpha, light, disk);
      if (!(t.irradiance > 0.0) || !(t.lobe > 1e-6 * t.irradiance)) continue;
      truth = t.lobe;
      if (disk)
        e.disk = ref::DiskLight{light.c, light.ex, light.ey, one};
      else
        e.rect = ref::RectLight{light.c, light.ex, light.ey, one};
    }
    errors.push_back(std::abs(model(e).x / (truth / area) - 1.0));
  }
  std::sort(errors.begin(), errors.end());
  return errors;
}

std::string num(double x) { return printfDouble("%.3g", x); }

}  // namespace

bool hasLightMethods(const ShaderLibrary& lib, const MaterialDesc& material) {
  const ShadingModel* model = lib.findModel(material.model);
  if (!model || !ref::ModelRegistry::instance().find(material.model)) return false;
  auto hasInput = [&](const char* name) {
    return std::any_of(model->inputs.begin(), model->inputs.end(), [&](const ModelInput& i) { return i.name == name; });
  };
  return hasInput("metallic") && hasInput("baseColor") &&
         std::any_of(kAreaLights.begin(), kAreaLights.end(), [&](LightType t) {
           return std::find(model->lights.begin(), model->lights.end(), t) != model->lights.end();
         });
}

std::vector<LightMethodRow> measureLightMethods(harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                                const MaterialDesc& material, const LightMethodOptions& options,
                                                const std::vector<LightType>& only) {
  const ShadingModel& model = *lib.findModel(material.model);
  const ref::ModelReferenceFn reference = ref::ModelRegistry::instance().find(material.model);
  const auto table = probeLtcTable(lib);
  std::vector<LightMethodRow> rows;
  for (LightType light : kAreaLights) {
    if (std::find(model.lights.begin(), model.lights.end(), light) == model.lights.end()) continue;
    if (!only.empty() && std::find(only.begin(), only.end(), light) == only.end()) continue;
    const LightMethodChoice* choice = model.findLightMethod(light);
    for (const std::string& method : choice ? choice->methods : std::vector<std::string>{""}) {
      MaterialDesc m = material;
      if (!method.empty()) m.lightMethods[lightTypeName(light)] = method;
      Permutation perm;
      perm.material = &m;
      perm.lights = {light};
      perm.environment = EnvironmentMode::None;
      const ProbeProgram probe = buildPermutationProbe(lib, perm);
      LightMethodRow row;
      row.light = light;
      row.method = method;
      row.readsLtcTable = perm.readsLtcTable();
      row.cost = measurePermutationCost(gpu, lib, perm, probe, options.cost).measured;
      const std::vector<double> errors =
          methodErrors(reference, referenceInput(lib, perm, table), light, options.lights, options.seed);
      auto at = [&](double q) { return errors[static_cast<size_t>(q * static_cast<double>(errors.size() - 1))]; };
      row.lights = options.lights;
      row.errorMedian = at(0.5);
      row.errorP95 = at(0.95);
      row.errorMax = errors.back();
      rows.push_back(row);
    }
  }
  return rows;
}

std::vector<LightType> areaLightsOf(const std::vector<LightType>& lights) {
  std::vector<LightType> out;
  for (LightType t : kAreaLights)
    if (std::find(lights.begin(), lights.end(), t) != lights.end()) out.push_back(t);
  return out;
}

std::string lightMethodLabel(const LightMethodRow& row) {
  return lightTypeName(row.light) + (row.method.empty() ? "" : ": " + row.method);
}

nlohmann::json toJson(const std::vector<LightMethodRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows)
    out.push_back({{"light", lightTypeName(r.light)},
                   {"method", r.method},
                   {"reads_ltc_table", r.readsLtcTable},
                   {"ns_per_eval", r.cost.nsPerEval},
                   {"ns_per_eval_low", r.cost.nsPerEvalLow},
                   {"ns_per_eval_high", r.cost.nsPerEvalHigh},
                   {"cost_resolved", r.cost.resolved},
                   {"lights", r.lights},
                   {"error_median", r.errorMedian},
                   {"error_p95", r.errorP95},
                   {"error_max", r.errorMax}});
  return out;
}

std::string lightMethodsMarkdown(const std::vector<LightMethodRow>& rows) {
  std::ostringstream md;
  md << "| light: method | ns/eval (95 % interval) | median \\|ratio − 1\\| | 95th percentile | worst |\n"
     << "|---|---:|---:|---:|---:|\n";
  for (const auto& r : rows)
    md << "| " << lightMethodLabel(r) << " | " << num(r.cost.nsPerEval) << " (" << num(r.cost.nsPerEvalLow) << "–"
       << num(r.cost.nsPerEvalHigh) << ") | " << num(r.errorMedian) << " | " << num(r.errorP95) << " | "
       << num(r.errorMax) << " |\n";
  return md.str();
}

std::string lightMethodsSvg(const std::vector<LightMethodRow>& rows, const std::string& subtitle) {
  const double W = 720, H = 440, left = 70, right = 200, top = 50, bottom = 50;
  double xLo = 1e300, xHi = 0, yLo = 1e300, yHi = 0;
  for (const auto& r : rows) {
    xLo = std::min(xLo, r.cost.nsPerEvalLow);
    xHi = std::max(xHi, r.cost.nsPerEvalHigh);
    yLo = std::min(yLo, std::max(r.errorMedian, 1e-7));
    yHi = std::max(yHi, r.errorP95);
  }
  xLo = std::pow(10, std::floor(std::log10(std::max(xLo, 1e-3))));
  xHi = std::pow(10, std::ceil(std::log10(xHi)));
  yLo = std::pow(10, std::floor(std::log10(yLo)));
  yHi = std::pow(10, std::ceil(std::log10(yHi)));
  auto px = [&](double x) { return left + (W - left - right) * std::log10(x / xLo) / std::log10(xHi / xLo); };
  auto py = [&](double y) {
    return H - bottom - (H - top - bottom) * std::log10(std::max(y, yLo) / yLo) / std::log10(yHi / yLo);
  };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left
    << "\" y=\"20\" font-size=\"15\">Area lights: run time against error, per shape and "
       "method</text>\n<text x=\""
    << left << "\" y=\"36\" fill=\"#555\">" << subtitle << "</text>\n";
  for (double x = xLo; x <= xHi * 1.0001; x *= 10)
    s << "<line x1=\"" << px(x) << "\" y1=\"" << top << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom
      << "\" stroke=\"#ddd\"/><text x=\"" << px(x) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">"
      << num(x) << "</text>\n";
  for (double y = yLo; y <= yHi * 1.0001; y *= 10)
    s << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y)
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">" << num(y)
      << "</text>\n";
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12
    << "\" text-anchor=\"middle\">ns per evaluation (permutation with that one light; bar: 95 % interval)</text>\n"
    << "<text transform=\"translate(16," << (top + H - bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">|ours / integral - 1|: median (dot) to 95th percentile</text>\n";
  const std::map<std::string, std::string> colours{
      {"sphere", "#1f77b4"}, {"tube", "#d62728"}, {"rect", "#2ca02c"}, {"disk", "#9467bd"}};
  int k = 0;
  for (const auto& r : rows) {
    const std::string colour = colours.at(lightTypeName(r.light));
    const bool ltc = r.readsLtcTable;
    const double x = px(r.cost.nsPerEval), y = py(r.errorMedian);
    s << "<line x1=\"" << px(r.cost.nsPerEvalLow) << "\" y1=\"" << y << "\" x2=\"" << px(r.cost.nsPerEvalHigh)
      << "\" y2=\"" << y << "\" stroke=\"" << colour << "\"/>\n"
      << "<line x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << x << "\" y2=\"" << py(r.errorP95) << "\" stroke=\""
      << colour << "\" stroke-dasharray=\"3,2\"/>\n"
      << (ltc ? "<circle cx=\"" + std::to_string(x) + "\" cy=\"" + std::to_string(y) + "\" r=\"5\""
              : "<rect x=\"" + std::to_string(x - 5) + "\" y=\"" + std::to_string(y - 5) +
                    "\" width=\"10\" height=\"10\"")
      << " fill=\"" << colour << "\"/>\n"
      << "<text x=\"" << W - right + 12 << "\" y=\"" << top + 16 * k << "\" fill=\"" << colour << "\">"
      << (ltc ? "&#9679; " : "&#9632; ") << lightMethodLabel(r) << "</text>\n";
    ++k;
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace mb::bench
