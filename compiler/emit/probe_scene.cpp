#include "emit/probe_scene.hpp"

#include <algorithm>
#include <numbers>

#include "emit/light_contract.hpp"

namespace mb {
namespace {

// Distances keep 1/d^2 <= 16; intensities up to 4 (pre-exposed units): the scene stays in the
// range where a composition's absolute error is meaningful, while the falloff radius range
// straddles the distance range, so windowing reaches zero for some samples.
constexpr Range kIntensity{0.0, 4.0};
constexpr Range kDistance{0.25, 20.0};
constexpr Range kFalloffRadius{0.5, 40.0};
constexpr Range kPrefiltered{0.0, 4.0};
// Rectangle and disk lights: luminance (pre-exposed units), so the irradiance reaches pi times it.
constexpr Range kLuminance{0.0, 4.0};

void lightInputs(LightType type, std::vector<ProbeSceneInput>& out) {
  auto add = [&](const std::string& name, ValueType t, Range r) { out.push_back({lightTypeName(type) + name, t, r}); };
  if (type == LightType::Dir) return;  // l and the optional illuminance
  if (isLtcLight(type)) {
    // Centred on l at Distance; the edges (semi-axes) turned by AxisAngle about l and the
    // second tilted by Tilt from facing the point (0 and pi: edge-on). Sizes are fractions of
    // the distance; a negative HalfWidth turns the light's back to the point (no light).
    // HalfHeight stays below 1, so the light stays at least a tenth of its distance from the
    // point (a point on an emitter has no meaningful fp32 polygon: the bricks' domains).
    add("Luminance", ValueType::Vec3, kLuminance);
    add("Distance", ValueType::Float, kDistance);
    add("AxisAngle", ValueType::Float, {0.0, std::numbers::pi});
    add("Tilt", ValueType::Float, {0.0, std::numbers::pi});
    add("HalfWidth", ValueType::Float, {-0.4, 1.5});
    add("HalfHeight", ValueType::Float, {0.0, 0.9});
    return;
  }
  add("Intensity", ValueType::Vec3, kIntensity);
  add("Distance", ValueType::Float, kDistance);
  add("FalloffRadius", ValueType::Float, kFalloffRadius);
  if (type == LightType::Spot) {
    add("AxisAngle", ValueType::Float, {0.0, 1.5});  // between the axis and -l, radians
    add("CosOuter", ValueType::Float, {0.2, 0.98});
    add("InnerFraction", ValueType::Float, {0.0, 1.0});  // cosInner = cosOuter + f (1 - cosOuter)
  } else if (type == LightType::Sphere) {
    add("RadiusFraction", ValueType::Float, {0.0, 0.9});  // radius / distance = sin(alpha)
  } else if (type == LightType::Tube) {
    add("AxisAngle", ValueType::Float, {0.0, std::numbers::pi});  // around l
    add("AxisTilt", ValueType::Float, {-1.0, 1.0});               // towards l
    add("HalfLengthFraction", ValueType::Float, {0.0, 2.0});      // of the distance
    add("RadiusFraction", ValueType::Float, {0.0, 0.3});
  }
}

}  // namespace

bool ProbeScene::has(LightType light) const { return std::find(lights.begin(), lights.end(), light) != lights.end(); }

bool ProbeScene::recordLtcTexel() const { return ltcTable && !ltcTableBuffer; }

std::vector<ProbeSceneInput> probeSceneInputs(const ProbeScene& scene) {
  std::vector<ProbeSceneInput> out;
  if (scene.has(LightType::Dir) && scene.illuminanceInput) out.push_back({"illuminance", ValueType::Vec3, {0.0, 1.0}});
  if (scene.fullFrame) {
    out.push_back({"ngTilt", ValueType::Float, {0.0, 0.5}});
    out.push_back({"tangentAngle", ValueType::Float, {0.0, std::numbers::pi}});
  }
  for (LightType type : scene.lights) lightInputs(type, out);
  if (scene.environment != EnvironmentMode::None) {
    // Radiance SH of a plausible environment: a positive mean and weaker higher bands.
    out.push_back({"sh0", ValueType::Vec3, {0.0, 2.0}});
    for (int i = 1; i < 9; ++i) out.push_back({"sh" + std::to_string(i), ValueType::Vec3, {-0.5, 0.5}});
    out.push_back({"ao", ValueType::Float, {0.0, 1.0}});
  }
  if (isIbl(scene.environment)) out.push_back({"prefiltered", ValueType::Vec3, kPrefiltered});
  if (scene.recordLtcTexel()) {
    // The LTC table's texel: M^-1 within the table's ranges for roughness >= 0.05 (as the
    // polygon bricks' domains), norm = Int D V (n.l) <= 1 and its Fresnel part below it.
    out.push_back({"ltcM00", ValueType::Float, {0.05, 1.0}});
    out.push_back({"ltcM02", ValueType::Float, {0.0, 0.6}});
    out.push_back({"ltcM20", ValueType::Float, {-0.3, 0.0}});
    out.push_back({"ltcM22", ValueType::Float, {0.05, 1.7}});
    out.push_back({"ltcNorm", ValueType::Float, {0.45, 1.0}});
    out.push_back({"ltcFresnel", ValueType::Float, {0.0, 0.45}});
    if (scene.ltcSheen) {
      // The sheen table's texel, within its ranges where the sheen is not negligible (roughness
      // >= 0.05 and norm >= 1e-3: the *_ltc_sheen_cv bricks' domains).
      out.push_back({"ltcSheenM00", ValueType::Float, {0.8, 1.33}});
      out.push_back({"ltcSheenM02", ValueType::Float, {-5.0, 0.0}});
      out.push_back({"ltcSheenM20", ValueType::Float, {0.0, 1.2}});
      out.push_back({"ltcSheenM22", ValueType::Float, {0.1, 2.2}});
      out.push_back({"ltcSheenNorm", ValueType::Float, {0.001, 1.0}});
    }
  }
  if (usesDfgLut(scene.environment)) {
    // DFG LUT texels: Int Gv Fc <= Int Gv <= 1 in Filament's LUT.
    out.push_back({"dfgX", ValueType::Float, {0.0, 0.45}});
    out.push_back({"dfgY", ValueType::Float, {0.45, 1.0}});
    out.push_back({"dfgZ", ValueType::Float, {0.0, 1.0}});
  }
  return out;
}

double probeSceneRadianceBound(const ProbeScene& scene) {
  double bound = 0;
  for (LightType type : scene.lights) {
    if (type == LightType::Dir)
      bound += 1.0;
    else if (isLtcLight(type))
      bound += std::numbers::pi * kLuminance.hi;  // irradiance Int L (n.l)+ dw <= pi L
    else
      bound += kIntensity.hi / (kDistance.lo * kDistance.lo);
  }
  if (scene.environment != EnvironmentMode::None) {
    // |E(n)| <= pi (|L00| + 2/3 sum |L1m| + 1/4 sum |L2m|) * sqrt(4 pi)-ish; 4 pi covers it.
    bound += 4.0 * std::numbers::pi * (2.0 + 8 * 0.5);
    // The probe's environment shape is at most (1.5 + 0.875)(1 + kProbeMaxMip / 8).
    bound += kPrefiltered.hi * 2.375 * (1.0 + 0.125 * kProbeMaxMip);
  }
  return std::max(bound, 1.0);
}

std::vector<std::string> probeSceneGlobals(const ProbeScene& scene) {
  std::vector<std::string> g;
  if (scene.fullFrame || scene.has(LightType::Spot) || scene.has(LightType::Tube) || scene.ltcTable) {
    // The frame's tangent and the spot and tube axes turn by an input angle, and the reference
    // reads that angle exactly (probe_scene_reference.cpp). GLSL sin and cos are bounded by the
    // Vulkan spec only to 2^-11 absolute ("Precision of GLSL.std.450 Instructions"); SwiftShader
    // errs by 1.9e-4 (docs/devices.md), which moved a narrow spot cone's edge by far more than
    // any brick's tolerance. So the probe evaluates them with + and * alone, which the spec
    // rounds correctly: Taylor series about pi/2 (pi/2 split in two floats, Cody and Waite),
    // truncated below 7e-10 on [0, pi]; ~2e-7 absolute after rounding.
    g.push_back("void mb_probe_sincos(float a, out float s, out float c) {");
    g.push_back("    float x = (a - 1.57079637) + 4.37113900e-8;  // a - pi/2");
    g.push_back("    float x2 = x * x;");
    g.push_back("    s = 1.0 + x2 * (-0.5 + x2 * (4.16666667e-2 + x2 * (-1.38888889e-3 + x2 * (2.48015873e-5 +");
    g.push_back("        x2 * (-2.75573192e-7 + x2 * (2.08767570e-9 + x2 * -1.14707456e-11))))));  // cos(x)");
    g.push_back("    c = -x * (1.0 + x2 * (-1.66666667e-1 + x2 * (8.33333333e-3 + x2 * (-1.98412698e-4 +");
    g.push_back("        x2 * (2.75573192e-6 + x2 * (-2.50521084e-8 + x2 * 1.60590438e-10))))));  // -sin(x)");
    g.push_back("}");
  }
  if (scene.recordLtcTexel()) {
    g.push_back("// The LTC table's fetches: the record's texel for every lookup (as the DFG texel).");
    g.push_back("vec4 mbProbeLtcMatrix;");
    g.push_back("vec2 mbProbeLtcMagnitude;");
    g.push_back("vec4 mb_fetch_ltc_matrix(float NoV, float perceptualRoughness) {");
    g.push_back("    return mbProbeLtcMatrix;");
    g.push_back("}");
    g.push_back("vec2 mb_fetch_ltc_magnitude(float NoV, float perceptualRoughness) {");
    g.push_back("    return mbProbeLtcMagnitude;");
    g.push_back("}");
    if (scene.ltcSheen) {
      g.push_back("vec4 mbProbeLtcSheenMatrix;");
      g.push_back("vec2 mbProbeLtcSheenMagnitude;");
      g.push_back("vec4 mb_fetch_ltc_sheen_matrix(float NoV, float perceptualRoughness) {");
      g.push_back("    return mbProbeLtcSheenMatrix;");
      g.push_back("}");
      g.push_back("vec2 mb_fetch_ltc_sheen_magnitude(float NoV, float perceptualRoughness) {");
      g.push_back("    return mbProbeLtcSheenMagnitude;");
      g.push_back("}");
    }
  }
  if (scene.environment == EnvironmentMode::None) return g;
  g.push_back("// The probe's environment fetches: record values shaped by a smooth known function of");
  g.push_back("// the lookup direction and level (mirrored by ref::probeEnvironmentShape).");
  g.push_back("vec3 mbProbePrefiltered;");
  g.push_back("vec3 mbProbeDfg;");
  g.push_back("float mb_probe_environment_shape(vec3 r, float lod) {");
  g.push_back("    return (1.5 + 0.5 * r.x + 0.25 * r.y - 0.125 * r.z) * (1.0 + 0.125 * lod);");
  g.push_back("}");
  g.push_back("vec3 mb_fetch_prefiltered(vec3 r, float lod) {");
  g.push_back("    return mbProbePrefiltered * mb_probe_environment_shape(r, lod);");
  g.push_back("}");
  g.push_back("vec3 mb_fetch_dfg(float NoV, float perceptualRoughness) {");
  g.push_back("    return mbProbeDfg;");
  g.push_back("}");
  return g;
}

std::vector<std::string> probeSceneFrame(const ProbeScene& scene) {
  std::vector<std::string> s;
  s.push_back("ShadingFrame f;");
  s.push_back("f.n = normalize(p_n);");
  s.push_back("f.v = normalize(p_v);");
  s.push_back("vec3 mbT0, mbB0;");
  s.push_back("mb_orthonormal_basis(f.n, mbT0, mbB0);");
  if (scene.fullFrame) {
    s.push_back("f.ng = normalize(f.n + p_ngTilt * mbB0);");
    s.push_back("float mbSinT, mbCosT;");
    s.push_back("mb_probe_sincos(p_tangentAngle, mbSinT, mbCosT);");
    s.push_back("f.t = mbCosT * mbT0 + mbSinT * mbB0;");
  } else {
    s.push_back("f.ng = f.n;");
    s.push_back("f.t = mbT0;");
  }
  if (scene.recordLtcTexel()) {
    s.push_back("mbProbeLtcMatrix = vec4(p_ltcM00, p_ltcM02, p_ltcM20, p_ltcM22);");
    s.push_back("mbProbeLtcMagnitude = vec2(p_ltcNorm, p_ltcFresnel);");
    if (scene.ltcSheen) {
      s.push_back("mbProbeLtcSheenMatrix = vec4(p_ltcSheenM00, p_ltcSheenM02, p_ltcSheenM20, p_ltcSheenM22);");
      s.push_back("mbProbeLtcSheenMagnitude = vec2(p_ltcSheenNorm, 0.0);");
    }
  }
  if (scene.environment != EnvironmentMode::None) {
    // Before preparePixel: an IBL mode fetches the DFG texel while preparing the pixel.
    bool ibl = isIbl(scene.environment);
    s.push_back(std::string("mbProbePrefiltered = ") + (ibl ? "p_prefiltered" : "vec3(0.0)") + ";");
    s.push_back(std::string("mbProbeDfg = ") +
                (usesDfgLut(scene.environment) ? "vec3(p_dfgX, p_dfgY, p_dfgZ)" : "vec3(0.0, 1.0, 0.0)") + ";");
  }
  return s;
}

std::vector<std::string> probeSceneShading(const ProbeScene& scene) {
  std::vector<std::string> s;
  s.push_back("vec3 lu = normalize(p_l);");
  s.push_back("vec3 lt, lb;");
  s.push_back("mb_orthonormal_basis(lu, lt, lb);");
  for (LightType type : scene.lights) {
    if (type == LightType::Dir) {
      s.push_back(std::string("r += shadeDirectionalLight(px, f, DirectionalLight(lu, ") +
                  (scene.illuminanceInput ? "p_illuminance" : "vec3(1.0)") + "));");
    } else if (type == LightType::Point) {
      s.push_back(
          "r += shadePointLight(px, f, PointLight(lu * p_pointDistance, p_pointIntensity, "
          "p_pointFalloffRadius));");
    } else if (type == LightType::Spot) {
      s.push_back("{");
      s.push_back("    float sinA, cosA;");
      s.push_back("    mb_probe_sincos(p_spotAxisAngle, sinA, cosA);");
      s.push_back("    vec3 axis = -cosA * lu + sinA * lt;");
      s.push_back("    float cosInner = p_spotCosOuter + p_spotInnerFraction * (1.0 - p_spotCosOuter);");
      s.push_back(
          "    r += shadeSpotLight(px, f, SpotLight(lu * p_spotDistance, axis, p_spotIntensity, "
          "p_spotFalloffRadius, p_spotCosOuter, cosInner));");
      s.push_back("}");
    } else if (type == LightType::Sphere) {
      s.push_back(
          "r += shadeSphereLight(px, f, SphereLight(lu * p_sphereDistance, p_sphereRadiusFraction * "
          "p_sphereDistance, p_sphereIntensity, p_sphereFalloffRadius));");
    } else if (type == LightType::Tube) {
      s.push_back("{");
      s.push_back("    float sinA, cosA;");
      s.push_back("    mb_probe_sincos(p_tubeAxisAngle, sinA, cosA);");
      s.push_back("    vec3 axis = normalize(cosA * lt + sinA * lb + p_tubeAxisTilt * lu);");
      s.push_back("    vec3 center = lu * p_tubeDistance;");
      s.push_back("    vec3 halfSegment = axis * (p_tubeHalfLengthFraction * p_tubeDistance);");
      s.push_back(
          "    r += shadeTubeLight(px, f, TubeLight(center - halfSegment, center + halfSegment, "
          "p_tubeRadiusFraction * p_tubeDistance, p_tubeIntensity, p_tubeFalloffRadius));");
      s.push_back("}");
    } else if (isLtcLight(type)) {
      const std::string p = "p_" + lightTypeName(type);
      s.push_back("{");
      s.push_back("    float sinA, cosA, sinT, cosT;");
      s.push_back("    mb_probe_sincos(" + p + "AxisAngle, sinA, cosA);");
      s.push_back("    mb_probe_sincos(" + p + "Tilt, sinT, cosT);");
      s.push_back("    vec3 e1 = cosA * lt + sinA * lb;");
      s.push_back("    vec3 e2 = cross(lu, e1);");
      s.push_back("    vec3 halfX = e1 * (" + p + "HalfWidth * " + p + "Distance);");
      s.push_back("    vec3 halfY = -(e2 * sinT + lu * cosT) * (" + p + "HalfHeight * " + p + "Distance);");
      s.push_back("    r += " + lightEntryPoint(type) + "(px, f, " + lightStructName(type) + "(lu * " + p +
                  "Distance, halfX, halfY, " + p + "Luminance));");
      s.push_back("}");
    }
  }
  if (scene.environment != EnvironmentMode::None) {
    s.push_back("{");
    s.push_back("    Environment env;");
    for (int i = 0; i < 9; ++i) s.push_back("    env.sh[" + std::to_string(i) + "] = p_sh" + std::to_string(i) + ";");
    s.push_back("    env.ao = p_ao;");
    s.push_back("    env.maxMip = " + std::to_string(static_cast<int>(kProbeMaxMip)) + ".0;");
    s.push_back("    r += shadeEnvironment(px, f, env);");
    s.push_back("}");
  }
  return s;
}

}  // namespace mb
