// Reference of the standard model's sheen (Filament "Physically Based Rendering in Filament"
// sec. 4.12.2; KHR_materials_sheen; seeds 000 "Fabric Material" and 004), in double:
//   sheen   = sheenColor D_s(h) V_s(l, v) (cosine)                  (sheen_d, sheen_v roles)
//   base   *= max(1 - max(sheenColor) E(n.v, r_s), 0)                (albedo scaling)
//   E       = the DFG LUT's cloth channel in ibl_lut, else the Enterprise PBR fit
//             0.65584461 (1 - n.v)^3 + 1 / (4.16526551 + exp(6.33516894 - 7.97291361 r_s))
//   IBL     = sheenColor E SO L_pre(reflect(-v, n), mip(r_s))
#include <algorithm>
#include <cmath>

#include "models/standard_reference.hpp"

namespace mb::ref::standard {
namespace {

double sheenAlbedoFit(double NoV, double perceptualRoughness) {
  double c = 1.0 - NoV;
  return 0.65584461 * c * c * c + 1.0 / (4.16526551 + std::exp(6.33516894 - 7.97291361 * perceptualRoughness));
}

// E(n.v, r_s): the probe's DFG texel z in ibl_lut (mb_fetch_dfg), the fit otherwise.
double sheenAlbedo(const ModelEvalInput& in, double NoV, double perceptualRoughness) {
  if (in.env && in.env->mode == "ibl_lut") return in.env->dfgAt(NoV, perceptualRoughness).z;
  return sheenAlbedoFit(NoV, perceptualRoughness);
}

}  // namespace

SheenPixel sheenPrepare(const ModelEvalInput& in, double NoV) {
  SheenPixel s;
  s.color = in.vec3Input("sheenColor");
  s.perceptualRoughness = in.floatInput("sheenRoughness");
  s.alpha = in.scalar("roughness", Args() << s.perceptualRoughness);
  double maxColor = std::max({s.color.x, s.color.y, s.color.z});
  // Never negative: the LUT's cloth channel can exceed 1 (docs/models/features.md).
  s.scaling = std::max(1.0 - maxColor * sheenAlbedo(in, NoV, s.perceptualRoughness), 0.0);
  return s;
}

Vec3 sheenDirect(const ModelEvalInput& in, const SheenPixel& s, const Vec3& l, const Vec3& lD, double cosine) {
  const ShadingFrame& f = in.frame;
  double D = in.scalar("sheen_d", Args().geometry(f.n, f.v, lD) << s.alpha);
  double V = in.scalar("sheen_v", Args().geometry(f.n, f.v, l) << s.alpha);
  // No lobe at a zero cosine or at v_charlie's pole (V infinite at n.l = 0; the limit of
  // V n.l is 0 there): inf * 0 would be NaN.
  if (!(cosine > 0.0) || std::isinf(V)) return {};
  return s.color * (D * V * cosine);
}

Vec3 sheenEnvironment(const ModelEvalInput& in, const SheenPixel& s, const Environment& env) {
  const ShadingFrame& f = in.frame;
  const Vec3 r = f.n * (2.0 * dot(f.n, f.v)) - f.v;  // reflect(-v, n)
  double NoV = makeGeometry(f.n, f.v, r).NoV;
  double lod = in.scalar("mip_mapping", Args() << s.perceptualRoughness << NoV << env.maxMip);
  double ao = env.ao * in.floatInput("ambientOcclusion");
  double occlusion =
      in.scalar("specular_occlusion", Args().geometry(f.n, f.v, r) << f.ng << ao << s.perceptualRoughness);
  // The albedo of sheenPrepare: at the pixel's n.v (the same value as g.NoV up to rounding).
  double albedo = sheenAlbedo(in, std::max(dot(f.n, f.v), kMinNoV), s.perceptualRoughness);
  return env.prefilteredAt(r, lod) * s.color * (albedo * occlusion);
}

}  // namespace mb::ref::standard
