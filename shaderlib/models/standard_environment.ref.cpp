// Reference of the standard model's environment light, in double, from the equations
// (docs/models/environment.md), independently of standard_environment.glsl:
//   L_d = diffuseColor * E_irr(n) / pi * ao                                    (all modes)
//   L_s = L_pref(r, lod) * E_spec * compensation(f0, Int Gv) * occlusion        (IBL modes)
//   L   = L_d (1 - E_spec) + L_s, then sheen and clear coat layered on top
// with E_spec the split-sum environment BRDF (Karis 2013, seed 002): from the DFG LUT texel
// (ibl_lut) or an analytic fit (ibl_analytic); r the mirror direction of v.
#include <algorithm>

#include "common/sh_diffuse_reference.hpp"
#include "models/standard_reference.hpp"

namespace mb::ref::standard {

namespace {

// Split-sum specular albedo of the base at the pixel's f0.
Vec3 specularAlbedo(const ModelEvalInput& in, const Pixel& px, const Environment& env) {
  if (env.mode == "ibl_lut") return in.vec3("dfg_lut", Args() << px.f0 << px.dfg.x << px.dfg.y);
  return in.vec3("env_brdf", Args() << px.f0 << px.perceptualRoughness << px.NoV);
}

}  // namespace

void environmentPrepare(const ModelEvalInput& in, Pixel& px) {
  const Environment& env = *in.env;
  if (env.mode == "ibl_lut") {
    px.dfg = env.dfgAt(px.NoV, px.perceptualRoughness);  // mb_fetch_dfg's texel
  } else {
    // E(f0) = f0 A + B for an affine env BRDF: E(0) = B = Int Gv Fc, E(1) = A + B = Int Gv.
    auto at = [&](double f0) { return in.vec3("env_brdf", Args() << splat(f0) << px.perceptualRoughness << px.NoV).x; };
    px.dfg = {at(0.0), at(1.0), 0.0};
  }
  px.energyCompensation = in.vec3("energy_compensation", Args() << px.f0 << px.dfg.y);
}

Vec3 shadeEnvironment(const ModelEvalInput& in, const Pixel& px, const Environment& env) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  const double ao = env.ao * px.ambientOcclusion;
  const Vec3 diffuse = shDiffuse(in, px.diffuseColor, env, ao);
  if (!env.ibl()) return diffuse;

  const Vec3 m = in.has("anisotropy") ? anisotropyIblNormal(in, px.anisotropy, px.perceptualRoughness) : n;
  const Vec3 r = m * (2.0 * dot(m, v)) - v;  // mirror of v about m
  const double NoR = std::min(std::max(dot(n, r), kMinNoV), 1.0);
  const double lod = in.scalar("mip_mapping", Args() << px.perceptualRoughness << NoR << env.maxMip);
  const Vec3 E = specularAlbedo(in, px, env);
  const double occlusion =
      in.scalar("specular_occlusion", Args().geometry(n, v, r) << in.frame.ng << ao << px.perceptualRoughness);
  const Vec3 specular = env.prefilteredAt(r, lod) * E * px.energyCompensation * occlusion;
  // The diffuse share 1 - E is clamped at 0 (E, an albedo, can exceed 1 in a LUT or fit).
  Vec3 color = diffuse * nonNegative(splat(1.0) - E) + specular;
  if (in.has("sheen")) color = color * px.sheen.scaling + sheenEnvironment(in, px.sheen, env);
  if (in.has("clearcoat")) {
    double attenuation = 1;
    const Vec3 coat = clearCoatEnvironment(in, px.clearCoat, env, attenuation);
    color = color * attenuation + coat;
  }
  return color;
}

}  // namespace mb::ref::standard
