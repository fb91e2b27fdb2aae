// Reference composition of the cloth model in double, written from the equations of seed 000
// "Fabric Material", seed 004 and Filament's cloth model (sec. 4.12), independently of
// cloth.glsl:
//   f(l, v) = baseColor fd(l) w(l) / cos + sheenColor D(h) V(l, v)   on the upper hemisphere
//   L_o     = [baseColor fd w(l) + sheenColor D V max(n.l, 0)] * E    (w: the wrap factor)
// Environment: SH9 irradiance / pi on the diffuse, the prefiltered sheen times the cloth DFG
// channel (docs/models/cloth.md).
#include <algorithm>

#include "common/model_reference.hpp"
#include "common/sh_diffuse_reference.hpp"

namespace mb::ref::cloth {

namespace {

struct Pixel {
  Vec3 diffuseColor, sheenColor, subsurfaceColor, emissive;
  double perceptualRoughness = 0, alpha = 0, wrap = 0, NoV = 0, ambientOcclusion = 1;
};

Pixel prepare(const ModelEvalInput& in) {
  Pixel px;
  px.diffuseColor = in.vec3Input("baseColor");
  px.perceptualRoughness = in.floatInput("roughness");
  px.alpha = in.scalar("roughness", Args() << px.perceptualRoughness);
  px.sheenColor = in.vec3Input("sheenColor");
  px.subsurfaceColor = in.vec3Input("subsurfaceColor");
  px.wrap = in.floatInput("wrap");
  px.NoV = std::max(dot(in.frame.n, in.frame.v), kMinNoV);
  px.emissive = in.vec3Input("emissive");
  px.ambientOcclusion = in.floatInput("ambientOcclusion");
  return px;
}

// Radiance per unit illuminance arriving from direction l (unit).
Vec3 light(const ModelEvalInput& in, const Pixel& px, const Vec3& l) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  const double fd = in.scalar("diffuse", Args().geometry(n, v, l) << px.perceptualRoughness << px.alpha);
  const Vec3 wrap = in.vec3("diffuse_wrap", Args().geometry(n, v, l) << px.wrap << px.subsurfaceColor);
  Vec3 color = px.diffuseColor * wrap * fd;
  const double cosine = dot(n, l);
  if (cosine > 0.0) {  // the sheen BRDF is defined on the upper hemisphere only
    const double D = in.scalar("specular_d", Args().geometry(n, v, l) << px.alpha);
    const double V = in.scalar("specular_v", Args().geometry(n, v, l) << px.alpha);
    color = color + px.sheenColor * (D * V * std::min(cosine, 1.0));
  }
  return color;
}

// Filament's smooth spot cone, from its definition: the cosine to the axis mapped linearly
// from 0 at the outer cone to 1 at the inner one, clamped, squared.
double spotCone(const SpotLight& s, const Vec3& l) {
  const double width = std::max(s.cosInner - s.cosOuter, 1e-4);
  const double t = clamp01((dot(l * -1.0, s.axis) - s.cosOuter) / width);
  return t * t;
}

Vec3 environment(const ModelEvalInput& in, const Pixel& px, const Environment& env) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  const double ao = env.ao * px.ambientOcclusion;
  const Vec3 diffuse = shDiffuse(in, px.diffuseColor, env, ao);
  if (env.mode != "ibl_lut") return diffuse;
  // Directional albedo of the sheen: sheenColor times the LUT's cloth channel (Filament's
  // cloth specularDFG); the diffuse keeps the rest.
  const Vec3 E = px.sheenColor * env.dfgAt(px.NoV, px.perceptualRoughness).z;
  const Vec3 r = n * (2.0 * dot(n, v)) - v;
  const double NoR = std::min(std::max(dot(n, r), kMinNoV), 1.0);
  const double lod = in.scalar("mip_mapping", Args() << px.perceptualRoughness << NoR << env.maxMip);
  const double occlusion =
      in.scalar("specular_occlusion", Args().geometry(n, v, r) << in.frame.ng << ao << px.perceptualRoughness);
  // 1 - E clamped at 0, as the GLSL (the cloth channel exceeds 1 at grazing views).
  return diffuse * nonNegative(splat(1.0) - E) + env.prefilteredAt(r, lod) * E * occlusion;
}

Vec3 evaluateCloth(const ModelEvalInput& in) {
  const Pixel px = prepare(in);
  Vec3 color = px.emissive;
  if (in.dir) color = color + light(in, px, normalize(in.dir->l)) * in.dir->illuminance;
  if (in.point) {
    const PointLight& p = *in.point;
    const double falloff = in.scalar("light_falloff", Args() << p.toLight << p.falloffRadius);
    color = color + light(in, px, normalize(p.toLight)) * (p.intensity * falloff);
  }
  if (in.spot) {
    const SpotLight& s = *in.spot;
    const Vec3 l = normalize(s.toLight);
    const double falloff = in.scalar("light_falloff", Args() << s.toLight << s.falloffRadius);
    color = color + light(in, px, l) * (s.intensity * (falloff * spotCone(s, l)));
  }
  if (in.env) color = color + environment(in, px, *in.env);
  return color;
}

}  // namespace

MB_MODEL_REFERENCE("cloth", evaluateCloth);

}  // namespace mb::ref::cloth
