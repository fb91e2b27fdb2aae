// Reference of the standard model's clear coat (seed 000 "More PBR / Clear Coating
// Material"; Filament "Physically Based Rendering in Filament" sec. 4.9), in double, written
// from the equations (see docs/models/features.md):
//   f0'   = lerp(f0, F0ClearCoatToSurface(f0), c)                  (f0_clearcoat role)
//   r'    = clearcoat_base_roughness(r, r_c, c)   (seed 000: lerp(r, max(r, r_c), c), perceptual)
//   nc    = normalize(T x + B y + ng z), (x, y, z) = clearCoatNormal, (T, B, ng) the tangent
//           frame of the geometric normal (Filament's shading_tangentToWorld * clearCoatNormal;
//           T = t orthonormalized against ng, B = ng x T); nc = ng where (x, y, z) = 0
//   coat  = c Fc(l.h) D_c(h) V_c(l, v) (nc.l)  about the coat's normal nc, F0 = 0.04
//   base *= 1 - c Fc(l.h)
// Image-based: coat = c Fc(nc.v) SO L_pre(reflect(-v, nc), mip(r_c)), base *= 1 - c Fc(nc.v).
#include <algorithm>

#include "common/aniso_reference.hpp"
#include "models/standard_reference.hpp"

namespace mb::ref::standard {
namespace {

constexpr double kCoatF0 = 0.04;  // IOR 1.5: ((1.5 - 1) / (1.5 + 1))^2

// The coat's Fresnel reflectance times its strength for the geometry (nc, v, l).
double coatFresnel(const ModelEvalInput& in, const ClearCoatPixel& cc, const Vec3& l) {
  Vec3 F = in.vec3("clearcoat_fresnel", Args().geometry(cc.normal, in.frame.v, l) << splat(kCoatF0) << 1.0);
  return F.x * cc.strength;
}

// The tangent-space clearCoatNormal in world space, about the geometric normal's frame.
Vec3 coatNormal(const ModelEvalInput& in) {
  const Vec3 ts = in.vec3Input("clearCoatNormal");
  const AnisoFrame frame = anisoFrame(in.frame.ng, in.frame.t);
  const Vec3 nc = frame.t * ts.x + frame.b * ts.y + frame.n * ts.z;
  return dot(nc, nc) > 1e-12 ? normalize(nc) : in.frame.ng;
}

}  // namespace

ClearCoatPixel clearCoatPrepare(const ModelEvalInput& in, Vec3& f0, double& perceptualRoughness) {
  ClearCoatPixel cc;
  cc.strength = in.floatInput("clearCoat");
  cc.perceptualRoughness = in.floatInput("clearCoatRoughness");
  cc.alpha = in.scalar("roughness", Args() << cc.perceptualRoughness);
  cc.normal = coatNormal(in);
  f0 = mix(f0, in.vec3("f0_clearcoat", Args() << f0), cc.strength);
  perceptualRoughness =
      in.scalar("clearcoat_base_roughness", Args() << perceptualRoughness << cc.perceptualRoughness << cc.strength);
  return cc;
}

Vec3 clearCoatDirect(const ModelEvalInput& in, const ClearCoatPixel& cc, const Vec3& l, double& attenuation) {
  const Vec3 nc = cc.normal, v = in.frame.v;
  double D = in.scalar("clearcoat_d", Args().geometry(nc, v, l) << cc.alpha);
  double V = in.scalar("clearcoat_v", Args().geometry(nc, v, l) << cc.alpha);
  double Fc = coatFresnel(in, cc, l);
  attenuation = 1.0 - Fc;
  // chi+(nc.h) (Walter et al. 2007, eq. 33): h below the coat's plane (the viewer below nc's
  // horizon with the light above it) meets no coat microfacet.
  const Geometry g = makeGeometry(nc, v, l);
  if (!(g.NoH > 0.0)) return {};
  return splat(D * V * Fc * g.NoL);
}

Vec3 clearCoatEnvironment(const ModelEvalInput& in, const ClearCoatPixel& cc, const Environment& env,
                          double& attenuation) {
  const Vec3 nc = cc.normal, v = in.frame.v;
  const Vec3 r = nc * (2.0 * dot(nc, v)) - v;  // reflect(-v, nc)
  double Fc = coatFresnel(in, cc, r);
  attenuation = 1.0 - Fc;
  double NoV = makeGeometry(nc, v, r).NoV;  // max(nc.v, kMinNoV) = nc.r
  double lod = in.scalar("mip_mapping", Args() << cc.perceptualRoughness << NoV << env.maxMip);
  double ao = env.ao * in.floatInput("ambientOcclusion");
  double occlusion = in.scalar("specular_occlusion", Args().geometry(nc, v, r) << nc << ao << cc.perceptualRoughness);
  return env.prefilteredAt(r, lod) * (Fc * occlusion);
}

// Schlick's Fresnel split over the coat's table entry (F0 = 0.04, F90 = 1), as the base's LTC
// lobe (standard_lights.ref.cpp), times the strength; the attenuation of image-based light.
Vec3 clearCoatLtc(const ModelEvalInput& in, const ClearCoatPixel& cc, double coatIntegral, const LtcTexel& t,
                  double& attenuation) {
  const Vec3 nc = cc.normal, v = in.frame.v;
  const Vec3 r = nc * (2.0 * dot(nc, v)) - v;  // reflect(-v, nc)
  attenuation = 1.0 - coatFresnel(in, cc, r);
  return splat((kCoatF0 * (t.norm - t.fresnel) + t.fresnel) / t.norm * coatIntegral * cc.strength);
}

}  // namespace mb::ref::standard
