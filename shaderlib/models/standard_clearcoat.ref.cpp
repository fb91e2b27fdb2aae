// Reference of the standard model's clear coat (seed 000 "More PBR / Clear Coating
// Material"; Filament "Physically Based Rendering in Filament" sec. 4.9), in double, written
// from the equations (see docs/models/features.md):
//   f0'   = lerp(f0, F0ClearCoatToSurface(f0), c)                  (f0_clearcoat role)
//   r'    = clearcoat_base_roughness(r, r_c, c)   (seed 000: lerp(r, max(r, r_c), c), perceptual)
//   coat  = c Fc(l.h) D_c(h) V_c(l, v) (ng.l)  about the geometric normal ng, F0 = 0.04
//   base *= 1 - c Fc(l.h)
// Image-based: coat = c Fc(ng.v) SO L_pre(reflect(-v, ng), mip(r_c)), base *= 1 - c Fc(ng.v).
#include <algorithm>

#include "models/standard_reference.hpp"

namespace mb::ref::standard {
namespace {

constexpr double kCoatF0 = 0.04;  // IOR 1.5: ((1.5 - 1) / (1.5 + 1))^2

// The coat's Fresnel reflectance times its strength for the geometry (ng, v, l).
double coatFresnel(const ModelEvalInput& in, const ClearCoatPixel& cc, const Vec3& l) {
  Vec3 F = in.vec3("clearcoat_fresnel", Args().geometry(in.frame.ng, in.frame.v, l) << splat(kCoatF0) << 1.0);
  return F.x * cc.strength;
}

}  // namespace

ClearCoatPixel clearCoatPrepare(const ModelEvalInput& in, Vec3& f0, double& perceptualRoughness) {
  ClearCoatPixel cc;
  cc.strength = in.floatInput("clearCoat");
  cc.perceptualRoughness = in.floatInput("clearCoatRoughness");
  cc.alpha = in.scalar("roughness", Args() << cc.perceptualRoughness);
  f0 = mix(f0, in.vec3("f0_clearcoat", Args() << f0), cc.strength);
  perceptualRoughness =
      in.scalar("clearcoat_base_roughness", Args() << perceptualRoughness << cc.perceptualRoughness << cc.strength);
  return cc;
}

Vec3 clearCoatDirect(const ModelEvalInput& in, const ClearCoatPixel& cc, const Vec3& l, double& attenuation) {
  const Vec3 ng = in.frame.ng, v = in.frame.v;
  double D = in.scalar("clearcoat_d", Args().geometry(ng, v, l) << cc.alpha);
  double V = in.scalar("clearcoat_v", Args().geometry(ng, v, l) << cc.alpha);
  double Fc = coatFresnel(in, cc, l);
  attenuation = 1.0 - Fc;
  // chi+(ng.h) (Walter et al. 2007, eq. 33): h below the coat's plane (the viewer below ng's
  // horizon with the light above it) meets no coat microfacet.
  const Geometry g = makeGeometry(ng, v, l);
  if (!(g.NoH > 0.0)) return {};
  return splat(D * V * Fc * g.NoL);
}

Vec3 clearCoatEnvironment(const ModelEvalInput& in, const ClearCoatPixel& cc, const Environment& env,
                          double& attenuation) {
  const Vec3 ng = in.frame.ng, v = in.frame.v;
  const Vec3 r = ng * (2.0 * dot(ng, v)) - v;  // reflect(-v, ng)
  double Fc = coatFresnel(in, cc, r);
  attenuation = 1.0 - Fc;
  double NoV = makeGeometry(ng, v, r).NoV;  // max(ng.v, kMinNoV) = ng.r
  double lod = in.scalar("mip_mapping", Args() << cc.perceptualRoughness << NoV << env.maxMip);
  double ao = env.ao * in.floatInput("ambientOcclusion");
  double occlusion =
      in.scalar("specular_occlusion", Args().geometry(ng, v, r) << ng << ao << cc.perceptualRoughness);
  return env.prefilteredAt(r, lod) * (Fc * occlusion);
}

}  // namespace mb::ref::standard
