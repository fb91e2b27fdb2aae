#include "preview/preview_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/diagnostics.hpp"
#include "library/shader_library.hpp"

namespace mb::preview {
namespace {

using ref::Vec3;

// engine_frame.glsl's MbFrameBlock in std140 (GLSL 4.50 spec 7.6.2.2): every member is a
// vec4 or uvec4 (16-byte aligned), so the C++ layout is the same with no padding.
constexpr uint32_t kMaxLights = 4;  // MB_MAX_LIGHTS
struct DirectionalGpu {
  float direction[4], illuminance[4];
};
struct LocalGpu {
  float position[4], intensity[4], axis[4], params[4];
};
struct AreaGpu {
  float position[4], halfX[4], halfY[4], luminance[4];
};
struct FrameBlock {
  float cameraPosition[4];
  uint32_t lightCounts[4], lightCounts2[4];
  DirectionalGpu dirLights[kMaxLights];
  LocalGpu pointLights[kMaxLights], spotLights[kMaxLights], sphereLights[kMaxLights], tubeLights[kMaxLights];
  float sh[9][4];
  float environment[4];
  AreaGpu rectLights[kMaxLights], diskLights[kMaxLights];
};
static_assert(sizeof(FrameBlock) == 1872, "std140 size of MbFrameBlock");

std::array<float, 3> unit(double x, double y, double z) {
  const double l = std::sqrt(x * x + y * y + z * z);
  return {static_cast<float>(x / l), static_cast<float>(y / l), static_cast<float>(z / l)};
}

Vec3 v3(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

void copy3(float* dst, const std::array<float, 3>& a, float w) {
  dst[0] = a[0];
  dst[1] = a[1];
  dst[2] = a[2];
  dst[3] = w;
}

// The records and the count of a local light type in the block.
struct LocalSlots {
  LocalGpu* records;
  uint32_t* count;
};
LocalSlots localSlots(FrameBlock& b, LightType type) {
  if (type == LightType::Point) return {b.pointLights, &b.lightCounts[1]};
  if (type == LightType::Spot) return {b.spotLights, &b.lightCounts[2]};
  if (type == LightType::Sphere) return {b.sphereLights, &b.lightCounts[3]};
  return {b.tubeLights, &b.lightCounts2[0]};
}

}  // namespace

std::vector<LightType> parsePreviewLights(const std::vector<std::string>& names) {
  std::vector<LightType> types;
  for (const auto& name : names) {
    auto type = parseLightType(name);
    if (!type) {
      const auto& valid = allLightTypeNames();
      std::string list;
      for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
      throw DiagnosticError({{Severity::Error,
                              "E-PREVIEW-LIGHT",
                              {"<command line>", 0, 0},
                              "unknown light type '" + name + "' for --lights (valid: " + list + ")",
                              didYouMean(name, valid)}});
    }
    types.push_back(*type);
  }
  return types;
}

std::vector<PreviewLight> defaultLights(const std::vector<LightType>& types) {
  std::vector<PreviewLight> lights;
  for (LightType type : types) {
    PreviewLight l;
    l.type = type;
    // Warm white key light from the upper left, in front; the others around the camera, far
    // enough from the unit sphere that their falloff windows (radius 12) barely cut in.
    if (type == LightType::Dir) {
      l.direction = unit(-1.0, 1.5, 1.2);
      l.intensity = {3.0f, 2.85f, 2.6f};
    } else if (type == LightType::Point) {
      l.position = {2.5f, 1.0f, 2.0f};
      l.intensity = {18.0f, 18.0f, 20.0f};
    } else if (type == LightType::Spot) {
      l.position = {0.0f, 3.0f, 2.0f};
      l.axis = unit(0.0, -3.0, -2.0);
      l.intensity = {30.0f, 28.0f, 24.0f};
      l.cosOuter = static_cast<float>(std::cos(25.0 * std::numbers::pi / 180.0));
      l.cosInner = static_cast<float>(std::cos(15.0 * std::numbers::pi / 180.0));
    } else if (type == LightType::Sphere) {
      l.position = {-2.0f, 2.0f, 2.5f};
      l.radius = 0.4f;
      l.intensity = {12.0f, 14.0f, 16.0f};
    } else if (isLtcLight(type)) {
      // A soft box above right and a round panel lower left, each facing the sphere's centre:
      // halfX across, halfY = facing x halfX, so that halfX x halfY points at the sphere.
      const bool rect = type == LightType::Rect;
      l.position = rect ? std::array<float, 3>{1.5f, 2.5f, 2.0f} : std::array<float, 3>{-2.5f, -1.0f, 2.0f};
      const Vec3 facing = ref::normalize(v3(l.position) * -1.0);
      const Vec3 across = ref::normalize(ref::cross(facing, Vec3{0, 1, 0}));
      const Vec3 up = ref::cross(facing, across);
      const double w = rect ? 0.8 : 0.5, h = rect ? 0.5 : 0.5;
      l.halfX = {static_cast<float>(across.x * w), static_cast<float>(across.y * w), static_cast<float>(across.z * w)};
      l.halfY = {static_cast<float>(up.x * h), static_cast<float>(up.y * h), static_cast<float>(up.z * h)};
      l.intensity = rect ? std::array<float, 3>{6.0f, 6.0f, 6.5f} : std::array<float, 3>{7.0f, 6.0f, 5.0f};
    } else {
      l.position = {1.0f, -1.5f, 2.5f};
      l.end = {2.5f, -0.5f, 2.0f};
      l.radius = 0.1f;
      l.intensity = {10.0f, 9.0f, 8.0f};
    }
    l.falloffRadius = type == LightType::Dir || isLtcLight(type) ? 0.0f : 12.0f;
    lights.push_back(l);
  }
  return lights;
}

std::array<float, 3> cameraPosition() { return {0.0f, 0.0f, static_cast<float>(kCameraDistance)}; }

std::array<float, 16> viewProjection() {
  // View: translate by -camera (the camera looks down -z with y up, no rotation).
  // Projection: right-handed perspective to Vulkan clip space, y flipped (framebuffer y is
  // down) and depth 0 at `near`, 1 at `far`.
  const double f = 1.0 / std::tan(kFieldOfViewDegrees * std::numbers::pi / 360.0);
  const double near = kCameraDistance - 1.5, far = kCameraDistance + 1.5;
  double p[16] = {};  // column-major
  p[0] = f;
  p[5] = -f;
  p[10] = far / (near - far);
  p[11] = -1.0;
  p[14] = near * far / (near - far);
  // Times the translation (0, 0, -d): column 3 becomes p * (0, 0, -d, 1).
  const double d = kCameraDistance;
  p[12] = 0.0;
  p[13] = 0.0;
  p[15] = d;  // -p[11] * d
  p[14] = p[14] - p[10] * d;
  std::array<float, 16> m{};
  for (int i = 0; i < 16; ++i) m[i] = static_cast<float>(p[i]);
  return m;
}

std::array<ref::Vec3, 9> frameSh(const EnvironmentMaps& env) {
  std::array<Vec3, 9> sh;
  for (int k = 0; k < 9; ++k)
    sh[k] = {static_cast<float>(env.sh[k][0]), static_cast<float>(env.sh[k][1]), static_cast<float>(env.sh[k][2])};
  return sh;
}

std::vector<uint8_t> frameBlockBytes(const std::vector<PreviewLight>& lights, const EnvironmentMaps* env) {
  FrameBlock b{};
  copy3(b.cameraPosition, cameraPosition(), 1.0f);
  for (const PreviewLight& l : lights) {
    if (l.type == LightType::Dir) {
      if (b.lightCounts[0] == kMaxLights) continue;
      DirectionalGpu& g = b.dirLights[b.lightCounts[0]++];
      copy3(g.direction, l.direction, 0.0f);
      copy3(g.illuminance, l.intensity, 0.0f);
      continue;
    }
    if (isLtcLight(l.type)) {
      uint32_t& count = l.type == LightType::Rect ? b.lightCounts2[1] : b.lightCounts2[2];
      if (count == kMaxLights) continue;
      AreaGpu& g = (l.type == LightType::Rect ? b.rectLights : b.diskLights)[count++];
      copy3(g.position, l.position, 0.0f);
      copy3(g.halfX, l.halfX, 0.0f);
      copy3(g.halfY, l.halfY, 0.0f);
      copy3(g.luminance, l.intensity, 0.0f);
      continue;
    }
    const LocalSlots slots = localSlots(b, l.type);
    if (*slots.count == kMaxLights) continue;
    LocalGpu& g = slots.records[(*slots.count)++];
    copy3(g.position, l.position, l.radius);
    copy3(g.intensity, l.intensity, l.falloffRadius);
    if (l.type == LightType::Spot) copy3(g.axis, l.axis, l.cosOuter);
    if (l.type == LightType::Tube) copy3(g.axis, l.end, 0.0f);
    g.params[0] = l.type == LightType::Spot ? l.cosInner : 0.0f;
  }
  if (env) {
    for (int k = 0; k < 9; ++k)
      for (int c = 0; c < 3; ++c) b.sh[k][c] = static_cast<float>(env->sh[k][c]);
    b.environment[0] = 1.0f;  // ambient occlusion
    b.environment[1] = static_cast<float>(env->maxMip());
  }
  std::vector<uint8_t> bytes(sizeof b);
  std::memcpy(bytes.data(), &b, sizeof b);
  return bytes;
}

bool setLight(const std::vector<PreviewLight>& lights, LightType type, size_t k, const ref::Vec3& worldPos,
              ref::ModelEvalInput& in) {
  size_t seen = 0;
  for (const PreviewLight& l : lights) {
    if (l.type != type || seen++ != k) continue;
    const Vec3 rel = v3(l.position) - worldPos;
    if (type == LightType::Dir) in.dir = ref::DirectionalLight{v3(l.direction), v3(l.intensity)};
    if (type == LightType::Point) in.point = ref::PointLight{rel, v3(l.intensity), l.falloffRadius};
    if (type == LightType::Spot)
      in.spot = ref::SpotLight{rel, v3(l.axis), v3(l.intensity), l.falloffRadius, l.cosOuter, l.cosInner};
    if (type == LightType::Sphere) in.sphere = ref::SphereLight{rel, l.radius, v3(l.intensity), l.falloffRadius};
    if (type == LightType::Tube)
      in.tube = ref::TubeLight{rel, v3(l.end) - worldPos, l.radius, v3(l.intensity), l.falloffRadius};
    if (type == LightType::Rect) in.rect = ref::RectLight{rel, v3(l.halfX), v3(l.halfY), v3(l.intensity)};
    if (type == LightType::Disk) in.disk = ref::DiskLight{rel, v3(l.halfX), v3(l.halfY), v3(l.intensity)};
    return true;
  }
  return false;
}

double sceneRadianceBound(const std::vector<PreviewLight>& lights, const EnvironmentMaps* env) {
  double bound = 0;
  for (const PreviewLight& l : lights) {
    const double peak = std::max({l.intensity[0], l.intensity[1], l.intensity[2]});
    if (l.type == LightType::Dir) {
      bound += peak;
      continue;
    }
    if (isLtcLight(l.type)) {
      bound += std::numbers::pi * peak;  // irradiance Int L (n.l)+ dw <= pi L
      continue;
    }
    // Closest approach of the light (its nearest point, for a tube) to the unit sphere.
    double d = std::sqrt(ref::dot(v3(l.position), v3(l.position)));
    if (l.type == LightType::Tube) d = std::min(d, std::sqrt(ref::dot(v3(l.end), v3(l.end))));
    d = std::max(d - 1.0 - l.radius, 0.25);
    bound += peak / (d * d);
  }
  if (env) {
    double texel = 0;
    for (const CubeLevel& level : env->levels)
      for (size_t i = 0; i < level.rgba.size(); ++i)
        if (i % 4 != 3) texel = std::max(texel, static_cast<double>(level.rgba[i]));
    // |E(n)| <= sum_l A_l max|Y_lm| sum_m |L_lm| with A = (pi, 2pi/3, pi/4) (Ramamoorthi and
    // Hanrahan 2001) and max|Y_0| = 0.2821, max|Y_1| = 0.4886, max|Y_2| = 1.0925.
    double irradiance = 0;
    for (int c = 0; c < 3; ++c) {
      double e = std::numbers::pi * 0.2821 * std::abs(env->sh[0][c]);
      for (int k = 1; k < 4; ++k) e += 2.0 * std::numbers::pi / 3.0 * 0.4886 * std::abs(env->sh[k][c]);
      for (int k = 4; k < 9; ++k) e += std::numbers::pi / 4.0 * 1.0925 * std::abs(env->sh[k][c]);
      irradiance = std::max(irradiance, e);
    }
    bound += texel + irradiance;
  }
  return std::max(bound, 1.0);
}

}  // namespace mb::preview
