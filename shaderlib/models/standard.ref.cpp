// Reference composition of the standard model, written independently of standard.glsl:
//   f(l, v) = diffuseColor * fd + D * V * F * compensation,   L_o = f * (n.l) * E
// with F0 = lerp(f0Dielectric, baseColor, metallic), diffuseColor = baseColor * (1 - metallic)
// (seed 003), each term evaluated by the double reference of the brick bound to its role,
// then the feature layers (sheen over the base, clear coat over both; seed 000 "More PBR").
#include "models/standard_reference.hpp"

namespace mb::ref::standard {

Pixel prepare(const ModelEvalInput& in) {
  Pixel px;
  Vec3 baseColor = in.vec3Input("baseColor");
  double metallic = in.floatInput("metallic");
  px.perceptualRoughness = in.floatInput("roughness");
  px.f0 = mix(in.vec3Input("f0Dielectric"), baseColor, metallic);
  px.diffuseColor = baseColor * (1.0 - metallic);
  px.NoV = std::max(dot(in.frame.n, in.frame.v), kMinNoV);
  px.emissive = in.vec3Input("emissive");
  px.ambientOcclusion = in.floatInput("ambientOcclusion");
  if (in.has("clearcoat")) px.clearCoat = clearCoatPrepare(in, px.f0, px.perceptualRoughness);
  px.alpha = in.scalar("roughness", Args() << px.perceptualRoughness);
  if (in.has("anisotropy")) px.anisotropy = anisotropyPrepare(in, px.alpha);
  if (in.env && in.env->ibl()) environmentPrepare(in, px);
  if (in.has("sheen")) px.sheen = sheenPrepare(in, px.NoV);
  return px;
}

Vec3 light(const ModelEvalInput& in, const Pixel& px, const Vec3& l, const Vec3& lD, double dScale, double diffuseCos,
           double specularCos) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  double D, V;
  if (in.has("anisotropy")) {
    anisotropyDV(in, px.anisotropy, l, lD, D, V);
  } else {
    D = in.scalar("specular_d", Args().geometry(n, v, lD) << px.alpha);
    V = in.scalar("specular_v", Args().geometry(n, v, l) << px.alpha);
  }
  Vec3 F = in.vec3(("fresnel"), Args().geometry(n, v, l) << px.f0 << 1.0);
  Vec3 specular = F * (D * dScale * V * specularCos) * px.energyCompensation;
  double fd = in.scalar("diffuse", Args().geometry(n, v, l) << px.perceptualRoughness << px.alpha);
  Vec3 color = px.diffuseColor * (fd * diffuseCos) + specular;
  if (in.has("sheen")) color = color * px.sheen.scaling + sheenDirect(in, px.sheen, l, lD, specularCos);
  if (in.has("clearcoat")) {
    double attenuation = 1;
    Vec3 coat = clearCoatDirect(in, px.clearCoat, l, attenuation);
    color = color * attenuation + coat;
  }
  return color;
}

static Vec3 evaluateStandard(const ModelEvalInput& in) {
  Pixel px = prepare(in);
  Vec3 color = px.emissive;
  if (in.dir) {
    const Vec3 l = normalize(in.dir->l);
    double NoL = clamp01(dot(in.frame.n, l));
    color = color + light(in, px, l, l, 1.0, NoL, NoL) * in.dir->illuminance;
  }
  if (in.point) color = color + shadePoint(in, px, *in.point);
  if (in.spot) color = color + shadeSpot(in, px, *in.spot);
  if (in.sphere) color = color + shadeSphere(in, px, *in.sphere);
  if (in.tube) color = color + shadeTube(in, px, *in.tube);
  if (in.rect) color = color + shadeRect(in, px, *in.rect);
  if (in.disk) color = color + shadeDisk(in, px, *in.disk);
  if (in.env) color = color + shadeEnvironment(in, px, *in.env);
  return color;
}

MB_MODEL_REFERENCE("standard", evaluateStandard);

}  // namespace mb::ref::standard
