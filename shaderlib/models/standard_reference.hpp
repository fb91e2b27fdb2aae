// The standard model's reference composition, in double (docs/models.md), split like its
// GLSL: standard.ref.cpp (pixel, BRDF of one light direction, directional light, the sum),
// standard_lights.ref.cpp, standard_environment.ref.cpp and one file per feature. Written
// from the seeds' equations, independently of the GLSL.
#pragma once
#include <algorithm>

#include "common/model_reference.hpp"

namespace mb::ref::standard {

struct ClearCoatPixel {
  double strength = 0, perceptualRoughness = 0, alpha = 0;
  Vec3 normal;  // the coat's unit normal, world space (clearCoatNormal)
};
struct AnisotropyPixel {
  double anisotropy = 0, at = 0, ab = 0;
};
struct SheenPixel {
  Vec3 color;
  double perceptualRoughness = 0, alpha = 0;
  double scaling = 1;  // the base layer's share: 1 - max(sheenColor) * sheen albedo
};

struct Pixel {
  Vec3 diffuseColor;
  double perceptualRoughness = 0, alpha = 0;
  Vec3 f0;
  double NoV = 0;
  Vec3 dfg{0, 1, 0};
  Vec3 energyCompensation{1, 1, 1};
  Vec3 emissive;
  double ambientOcclusion = 1;
  ClearCoatPixel clearCoat;
  AnisotropyPixel anisotropy;
  SheenPixel sheen;
};

Pixel prepare(const ModelEvalInput& in);
// Radiance per unit illuminance for the light direction l (unit, towards the light):
// diffuse, V and F at l; D at lD (an area light's representative direction; l for punctual
// lights) times dScale; diffuseCos and specularCos the cosine factors.
Vec3 light(const ModelEvalInput& in, const Pixel& px, const Vec3& l, const Vec3& lD, double dScale, double diffuseCos,
           double specularCos);

// standard_lights.ref.cpp
Vec3 shadePoint(const ModelEvalInput& in, const Pixel& px, const PointLight& light);
Vec3 shadeSpot(const ModelEvalInput& in, const Pixel& px, const SpotLight& light);
Vec3 shadeSphere(const ModelEvalInput& in, const Pixel& px, const SphereLight& light);
Vec3 shadeTube(const ModelEvalInput& in, const Pixel& px, const TubeLight& light);
Vec3 shadeRect(const ModelEvalInput& in, const Pixel& px, const RectLight& light);
Vec3 shadeDisk(const ModelEvalInput& in, const Pixel& px, const DiskLight& light);

// standard_environment.ref.cpp
void environmentPrepare(const ModelEvalInput& in, Pixel& px);  // IBL modes: dfg, compensation
Vec3 shadeEnvironment(const ModelEvalInput& in, const Pixel& px, const Environment& env);

// standard_clearcoat.ref.cpp
ClearCoatPixel clearCoatPrepare(const ModelEvalInput& in, Vec3& f0, double& perceptualRoughness);
// The coat's specular about its normal (clearCoatNormal) times its own n.l; `attenuation` is the
// base's share, 1 - strength * Fc.
Vec3 clearCoatDirect(const ModelEvalInput& in, const ClearCoatPixel& cc, const Vec3& l, double& attenuation);
Vec3 clearCoatEnvironment(const ModelEvalInput& in, const ClearCoatPixel& cc, const Environment& env,
                          double& attenuation);

// The coat under a rectangle or disk light (per unit luminance), from its lobe's integral over the
// light and its table entry `t` (the magnitudes); `attenuation` as for image-based light,
// 1 - strength Fc(nc.v).
Vec3 clearCoatLtc(const ModelEvalInput& in, const ClearCoatPixel& cc, double coatIntegral, const LtcTexel& t,
                  double& attenuation);
// Rectangle and disk lights use the LTC table's lobe, GGX at alpha = r^2, with r clamped to
// [kLtcMinRoughness, 1]: the table's fitted and validated domain (standard_lights.glsl).
inline constexpr double kLtcMinRoughness = 0.05;
// The LTC bricks' geometry starts at n.v = 0.001: the lobes' view is lifted to it
// (standard_lights.glsl, mb_ltc_view).
inline constexpr double kLtcMinNoV = 0.001;
inline double ltcRoughness(double perceptualRoughness) {
  return std::clamp(perceptualRoughness, kLtcMinRoughness, 1.0);
}

// standard_anisotropy.ref.cpp
AnisotropyPixel anisotropyPrepare(const ModelEvalInput& in, double alpha);
void anisotropyDV(const ModelEvalInput& in, const AnisotropyPixel& a, const Vec3& l, const Vec3& lD, double& D,
                  double& V);
Vec3 anisotropyIblNormal(const ModelEvalInput& in, const AnisotropyPixel& a, double perceptualRoughness);

// standard_sheen.ref.cpp
SheenPixel sheenPrepare(const ModelEvalInput& in, double NoV);
Vec3 sheenDirect(const ModelEvalInput& in, const SheenPixel& s, const Vec3& l, const Vec3& lD, double cosine);
Vec3 sheenEnvironment(const ModelEvalInput& in, const SheenPixel& s, const Environment& env);

}  // namespace mb::ref::standard
