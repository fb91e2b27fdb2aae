#include "preview/environment_radiance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "emit/glsl_writer.hpp"
#include "preview/dir_math.hpp"
#include "library/shader_library.hpp"

namespace mb::preview {
namespace {

constexpr double kPi = 3.14159265358979323846;

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}
void addScaled(Rgb& acc, const Rgb& v, double s) {
  for (int c = 0; c < 3; ++c) acc[c] += v[c] * s;
}

// Centre direction and axes of something at (azimuth, elevation): c = (cos e sin a, sin e,
// cos e cos a), u = (cos a, 0, -sin a) horizontal and orthogonal to c, v = c x u.
struct Frame {
  Dir c, u, v;
};
Frame frameAt(double azimuthDeg, double elevationDeg) {
  const double a = azimuthDeg * kPi / 180.0, e = elevationDeg * kPi / 180.0;
  Frame f;
  f.c = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
  f.u = {std::cos(a), 0.0, -std::sin(a)};
  f.v = {f.c[1] * f.u[2] - f.c[2] * f.u[1], f.c[2] * f.u[0] - f.c[0] * f.u[2], f.c[0] * f.u[1] - f.c[1] * f.u[0]};
  return f;
}

Rgb studioRadiance(const Dir& d) {
  const StudioParams& p = studioParams();
  const Rgb wall = mix(p.wall, p.wallTop, smoothstep(0.0, 1.0, d[1]));
  Rgb radiance = mix(p.ground, wall, smoothstep(-p.horizonBlend, 0.0, d[1]));
  for (const SoftBox& b : p.boxes) {
    const Frame f = frameAt(b.azimuthDeg, b.elevationDeg);
    const double c = dot(d, f.c);
    if (c <= 0.0) continue;
    const double x = std::abs(dot(d, f.u) / c), y = std::abs(dot(d, f.v) / c), s = p.softness;
    const double mask = (1.0 - smoothstep(b.halfWidth - s, b.halfWidth + s, x)) *
                        (1.0 - smoothstep(b.halfHeight - s, b.halfHeight + s, y));
    addScaled(radiance, b.radiance, mask);
  }
  return radiance;
}

Rgb skySmooth(const Dir& d) {
  const SkyParams& p = skyParams();
  const Dir s = frameAt(p.sunAzimuthDeg, p.sunElevationDeg).c;
  const double t = 1.0 - std::clamp(d[1], 0.0, 1.0);
  Rgb sky = mix(p.horizon, p.zenith, 1.0 - std::pow(t, 4.0));
  addScaled(sky, p.glow, std::exp((dot(d, s) - 1.0) / p.glowWidth));
  return mix(p.ground, sky, smoothstep(-p.horizonBlend, 0.0, d[1]));
}

Rgb skySun(const Dir& d) {
  const SkyParams& p = skyParams();
  const Dir s = frameAt(p.sunAzimuthDeg, p.sunElevationDeg).c;
  const Dir diff{d[0] - s[0], d[1] - s[1], d[2] - s[2]};
  const double gamma = 2.0 * std::asin(std::min(0.5 * std::sqrt(dot(diff, diff)), 1.0));
  const double disc = 1.0 - smoothstep(p.sunRadius - p.sunEdge, p.sunRadius + p.sunEdge, gamma);
  Rgb radiance{0, 0, 0};
  if (disc > 0.0) {
    const double r = std::min(gamma / p.sunRadius, 1.0);
    addScaled(radiance, p.sun, disc * (1.0 - p.limbDarkening * (1.0 - std::sqrt(1.0 - r * r))));
  }
  return radiance;
}

const PeakCone& sunCone() {
  static const PeakCone cone = [] {
    const SkyParams& p = skyParams();
    const Frame f = frameAt(p.sunAzimuthDeg, p.sunElevationDeg);
    const double half = p.sunRadius + p.sunEdge, sinHalf = std::sin(0.5 * half);
    return PeakCone{f.c, f.u, f.v, 2.0 * sinHalf * sinHalf};  // 1 - cos without cancellation
  }();
  return cone;
}

std::string vec3Glsl(const Dir& v) {
  return "vec3(" + glslFloat(v[0]) + ", " + glslFloat(v[1]) + ", " + glslFloat(v[2]) + ")";
}

void constant(GlslWriter& w, const std::string& type, const std::string& name, const std::string& value) {
  w.line("const " + type + " " + name + " = " + value + ";");
}

void studioConstants(GlslWriter& w) {
  const StudioParams& p = studioParams();
  const size_t n = p.boxes.size();
  std::string centre, u, v, half, radiance;
  for (size_t k = 0; k < n; ++k) {
    const SoftBox& b = p.boxes[k];
    const Frame f = frameAt(b.azimuthDeg, b.elevationDeg);
    const std::string sep = k ? ", " : "";
    centre += sep + vec3Glsl(f.c);
    u += sep + vec3Glsl(f.u);
    v += sep + vec3Glsl(f.v);
    half += sep + "vec2(" + glslFloat(b.halfWidth) + ", " + glslFloat(b.halfHeight) + ")";
    radiance += sep + vec3Glsl(b.radiance);
  }
  const std::string count = std::to_string(n);
  constant(w, "int", "kBoxCount", count);
  constant(w, "vec3", "kBoxCentre[" + count + "]", "vec3[](" + centre + ")");
  constant(w, "vec3", "kBoxU[" + count + "]", "vec3[](" + u + ")");
  constant(w, "vec3", "kBoxV[" + count + "]", "vec3[](" + v + ")");
  constant(w, "vec2", "kBoxHalf[" + count + "]", "vec2[](" + half + ")");
  constant(w, "vec3", "kBoxRadiance[" + count + "]", "vec3[](" + radiance + ")");
  constant(w, "float", "kBoxSoftness", glslFloat(p.softness));
  constant(w, "vec3", "kWall", vec3Glsl(p.wall));
  constant(w, "vec3", "kWallTop", vec3Glsl(p.wallTop));
  constant(w, "vec3", "kGround", vec3Glsl(p.ground));
  constant(w, "float", "kHorizonBlend", glslFloat(p.horizonBlend));
}

void skyConstants(GlslWriter& w) {
  const SkyParams& p = skyParams();
  constant(w, "vec3", "kSunDirection", vec3Glsl(frameAt(p.sunAzimuthDeg, p.sunElevationDeg).c));
  constant(w, "float", "kSunRadius", glslFloat(p.sunRadius));
  constant(w, "float", "kSunEdge", glslFloat(p.sunEdge));
  constant(w, "float", "kLimbDarkening", glslFloat(p.limbDarkening));
  constant(w, "vec3", "kSun", vec3Glsl(p.sun));
  constant(w, "vec3", "kZenith", vec3Glsl(p.zenith));
  constant(w, "vec3", "kHorizon", vec3Glsl(p.horizon));
  constant(w, "vec3", "kGlow", vec3Glsl(p.glow));
  constant(w, "float", "kGlowWidth", glslFloat(p.glowWidth));
  constant(w, "vec3", "kGround", vec3Glsl(p.ground));
  constant(w, "float", "kHorizonBlend", glslFloat(p.horizonBlend));
  const PeakCone& cone = sunCone();
  constant(w, "vec3", "kPeakAxis", vec3Glsl(cone.axis));
  constant(w, "vec3", "kPeakU", vec3Glsl(cone.u));
  constant(w, "vec3", "kPeakV", vec3Glsl(cone.v));
  constant(w, "float", "kPeakOneMinusCosMax", glslFloat(cone.oneMinusCosMax));
}

}  // namespace

// A key light front left, a cool fill right, a long strip overhead and a warm rim behind
// (the classic three-point setup plus a top light), about 20-30 degrees across: big enough
// to read as shapes in a sphere's reflection, soft over 2.3 degrees (3-4 texels of a 128 cube).
const StudioParams& studioParams() {
  static const StudioParams p{{{-40.0, 35.0, 0.35, 0.50, {9.0, 8.6, 8.0}},
                               {70.0, 15.0, 0.25, 0.60, {2.0, 2.2, 2.6}},
                               {0.0, 90.0, 0.12, 0.90, {5.0, 5.0, 5.0}},
                               {160.0, 20.0, 0.20, 0.40, {6.0, 5.6, 5.0}}},
                              0.04,
                              {0.045, 0.045, 0.05},
                              {0.02, 0.02, 0.024},
                              {0.12, 0.11, 0.10},
                              0.05};
  return p;
}

// Sun 35 degrees up; its disc 2.3 degrees across (the real sun's 0.53 would be under one
// texel of a 128 cube). Irradiance at normal incidence ~ pi r^2 x 3800 x 0.8 (limb) = 3.8,
// against ~0.9 from the sky on an upward normal (tests print E(up) = 3.1 with the sun at 35
// degrees): a clear day's 4:1, in a range a preview tonemaps well.
const SkyParams& skyParams() {
  static const SkyParams p{30.0,
                           35.0,
                           0.02,
                           0.004,
                           0.6,
                           {4000.0, 3800.0, 3400.0},
                           {0.35, 0.55, 1.0},
                           {1.0, 1.05, 1.1},
                           {1.2, 1.1, 0.9},
                           0.03,
                           {0.35, 0.31, 0.26},
                           0.04};
  return p;
}

Rgb environmentSmoothRadiance(const std::string& name, const Dir& d) {
  if (name == "studio") return studioRadiance(d);
  if (name == "sky") return skySmooth(d);
  throw std::out_of_range("unknown environment '" + name + "'");
}

Rgb environmentPeakRadiance(const std::string& name, const Dir& d) {
  if (name == "sky") return skySun(d);
  environmentSmoothRadiance(name, d);  // the name check
  return {0, 0, 0};
}

Rgb environmentRadiance(const std::string& name, const Dir& d) {
  Rgb radiance = environmentSmoothRadiance(name, d);
  addScaled(radiance, environmentPeakRadiance(name, d), 1.0);
  return radiance;
}

const PeakCone* environmentPeak(const std::string& name) { return name == "sky" ? &sunCone() : nullptr; }

void writeRadianceGlsl(GlslWriter& w, const ShaderLibrary& lib, const std::string& name) {
  if (name == "studio")
    studioConstants(w);
  else if (name == "sky")
    skyConstants(w);
  else
    throw std::out_of_range("unknown environment '" + name + "'");
  const std::string file = "environments/" + name + ".glsl";
  w.include(ShaderLibrary::displayPath(file), lib.source(file));
}

}  // namespace mb::preview
