#include "validate/probe_scene_reference.hpp"

#include <cmath>
#include <stdexcept>

namespace mb {
namespace {

using ref::Vec3;

// lights.glsl's mb_orthonormal_basis (Duff et al. 2017), in double.
void orthonormalBasis(const Vec3& n, Vec3& t, Vec3& b) {
  double s = n.z >= 0.0 ? 1.0 : -1.0;
  double a = -1.0 / (s + n.z);
  double c = n.x * n.y * a;
  t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

}  // namespace

SceneColumns sceneColumns(const ProbeScene& scene, const ProbeLayout& layout) {
  auto at = [&layout](const std::string& name) {
    const ProbeInput* in = layout.find(name);
    if (!in) throw std::logic_error("probe record has no input '" + name + "'");
    return in->offset;
  };
  SceneColumns c;
  c.n = at("n");
  c.v = at("v");
  c.l = at("l");
  if (scene.fullFrame) {
    c.ngTilt = at("ngTilt");
    c.tangentAngle = at("tangentAngle");
  }
  for (LightType type : scene.lights) {
    if (type == LightType::Dir) {
      if (scene.illuminanceInput) c.illuminance = at("illuminance");
    } else if (type == LightType::Point) {
      c.pointDistance = at("pointDistance");
      c.pointIntensity = at("pointIntensity");
      c.pointFalloffRadius = at("pointFalloffRadius");
    } else if (type == LightType::Spot) {
      c.spotAxisAngle = at("spotAxisAngle");
      c.spotCosOuter = at("spotCosOuter");
      c.spotInnerFraction = at("spotInnerFraction");
      c.spotDistance = at("spotDistance");
      c.spotIntensity = at("spotIntensity");
      c.spotFalloffRadius = at("spotFalloffRadius");
    } else if (type == LightType::Sphere) {
      c.sphereDistance = at("sphereDistance");
      c.sphereRadiusFraction = at("sphereRadiusFraction");
      c.sphereIntensity = at("sphereIntensity");
      c.sphereFalloffRadius = at("sphereFalloffRadius");
    } else if (type == LightType::Tube) {
      c.tubeAxisAngle = at("tubeAxisAngle");
      c.tubeDistance = at("tubeDistance");
      c.tubeAxisTilt = at("tubeAxisTilt");
      c.tubeHalfLengthFraction = at("tubeHalfLengthFraction");
      c.tubeRadiusFraction = at("tubeRadiusFraction");
      c.tubeIntensity = at("tubeIntensity");
      c.tubeFalloffRadius = at("tubeFalloffRadius");
    } else if (isLtcLight(type)) {
      const int k = type == LightType::Rect ? 0 : 1;
      const std::string name = lightTypeName(type);
      c.areaLuminance[k] = at(name + "Luminance");
      c.areaDistance[k] = at(name + "Distance");
      c.areaAxisAngle[k] = at(name + "AxisAngle");
      c.areaTilt[k] = at(name + "Tilt");
      c.areaHalfWidth[k] = at(name + "HalfWidth");
      c.areaHalfHeight[k] = at(name + "HalfHeight");
    }
  }
  if (scene.recordLtcTexel()) {
    c.ltcM00 = at("ltcM00");
    c.ltcM02 = at("ltcM02");
    c.ltcM20 = at("ltcM20");
    c.ltcM22 = at("ltcM22");
    c.ltcNorm = at("ltcNorm");
    c.ltcFresnel = at("ltcFresnel");
    if (scene.ltcSheen) {
      c.ltcSheenM00 = at("ltcSheenM00");
      c.ltcSheenM02 = at("ltcSheenM02");
      c.ltcSheenM20 = at("ltcSheenM20");
      c.ltcSheenM22 = at("ltcSheenM22");
      c.ltcSheenNorm = at("ltcSheenNorm");
    }
  }
  if (scene.environment == EnvironmentMode::None) return c;
  for (int i = 0; i < 9; ++i) c.sh[i] = at("sh" + std::to_string(i));
  c.ao = at("ao");
  if (isIbl(scene.environment)) c.prefiltered = at("prefiltered");
  if (usesDfgLut(scene.environment)) {
    c.dfgX = at("dfgX");
    c.dfgY = at("dfgY");
    c.dfgZ = at("dfgZ");
  }
  return c;
}

void sceneFromRecord(const ProbeScene& scene, const ProbeLayout& layout, const double* record,
                     ref::ModelEvalInput& in) {
  sceneFromRecord(scene, sceneColumns(scene, layout), record, in);
}

void sceneFromRecord(const ProbeScene& scene, const SceneColumns& c, const double* record, ref::ModelEvalInput& in) {
  auto scalar = [record](uint32_t at) { return record[at]; };
  auto vec3 = [record](uint32_t at) { return Vec3{record[at], record[at + 1], record[at + 2]}; };
  ref::ShadingFrame& f = in.frame;
  f.n = ref::normalize(vec3(c.n));
  f.v = ref::normalize(vec3(c.v));
  Vec3 t0, b0;
  orthonormalBasis(f.n, t0, b0);
  if (scene.fullFrame) {
    f.ng = ref::normalize(f.n + b0 * scalar(c.ngTilt));
    double a = scalar(c.tangentAngle);
    f.t = t0 * std::cos(a) + b0 * std::sin(a);
  } else {
    f.ng = f.n;
    f.t = t0;
  }
  const Vec3 lu = ref::normalize(vec3(c.l));
  Vec3 lt, lb;
  orthonormalBasis(lu, lt, lb);
  for (LightType type : scene.lights) {
    if (type == LightType::Dir) {
      in.dir = ref::DirectionalLight{lu, scene.illuminanceInput ? vec3(c.illuminance) : Vec3{1, 1, 1}};
    } else if (type == LightType::Point) {
      in.point = ref::PointLight{lu * scalar(c.pointDistance), vec3(c.pointIntensity), scalar(c.pointFalloffRadius)};
    } else if (type == LightType::Spot) {
      double a = scalar(c.spotAxisAngle), cosOuter = scalar(c.spotCosOuter);
      Vec3 axis = lt * std::sin(a) - lu * std::cos(a);
      double cosInner = cosOuter + scalar(c.spotInnerFraction) * (1.0 - cosOuter);
      in.spot = ref::SpotLight{lu * scalar(c.spotDistance), axis,     vec3(c.spotIntensity),
                               scalar(c.spotFalloffRadius), cosOuter, cosInner};
    } else if (type == LightType::Sphere) {
      double d = scalar(c.sphereDistance);
      in.sphere = ref::SphereLight{lu * d, scalar(c.sphereRadiusFraction) * d, vec3(c.sphereIntensity),
                                   scalar(c.sphereFalloffRadius)};
    } else if (type == LightType::Tube) {
      double a = scalar(c.tubeAxisAngle), d = scalar(c.tubeDistance);
      Vec3 axis = ref::normalize(lt * std::cos(a) + lb * std::sin(a) + lu * scalar(c.tubeAxisTilt));
      Vec3 center = lu * d, halfSegment = axis * (scalar(c.tubeHalfLengthFraction) * d);
      in.tube = ref::TubeLight{center - halfSegment, center + halfSegment, scalar(c.tubeRadiusFraction) * d,
                               vec3(c.tubeIntensity), scalar(c.tubeFalloffRadius)};
    } else if (isLtcLight(type)) {
      const int k = type == LightType::Rect ? 0 : 1;
      double a = scalar(c.areaAxisAngle[k]), tilt = scalar(c.areaTilt[k]), d = scalar(c.areaDistance[k]);
      Vec3 e1 = lt * std::cos(a) + lb * std::sin(a);
      Vec3 e2 = ref::cross(lu, e1);
      Vec3 halfX = e1 * (scalar(c.areaHalfWidth[k]) * d);
      Vec3 halfY = (e2 * std::sin(tilt) + lu * std::cos(tilt)) * (-scalar(c.areaHalfHeight[k]) * d);
      if (k == 0)
        in.rect = ref::RectLight{lu * d, halfX, halfY, vec3(c.areaLuminance[k])};
      else
        in.disk = ref::DiskLight{lu * d, halfX, halfY, vec3(c.areaLuminance[k])};
    }
  }
  if (scene.recordLtcTexel())
    in.ltc = ref::LtcTexel{scalar(c.ltcM00), scalar(c.ltcM02),  scalar(c.ltcM20),
                           scalar(c.ltcM22), scalar(c.ltcNorm), scalar(c.ltcFresnel)};
  if (scene.recordLtcTexel() && scene.ltcSheen)
    in.sheenLtc = ref::LtcTexel{scalar(c.ltcSheenM00), scalar(c.ltcSheenM02),  scalar(c.ltcSheenM20),
                                scalar(c.ltcSheenM22), scalar(c.ltcSheenNorm), 0.0};
  if (scene.environment == EnvironmentMode::None) return;
  // Filled in place: assigning a fresh Environment would copy its mode string and hooks per
  // record. The hooks stay unset (validation's probe has no textures).
  ref::Environment& env = in.env ? *in.env : in.env.emplace();
  if (env.mode != environmentModeName(scene.environment)) env.mode = environmentModeName(scene.environment);
  for (int i = 0; i < 9; ++i) env.sh[i] = vec3(c.sh[i]);
  env.ao = scalar(c.ao);
  env.maxMip = kProbeMaxMip;
  env.prefiltered = env.ibl() ? vec3(c.prefiltered) : Vec3{};
  env.dfg = usesDfgLut(scene.environment) ? Vec3{scalar(c.dfgX), scalar(c.dfgY), scalar(c.dfgZ)} : Vec3{0, 1, 0};
}

}  // namespace mb
