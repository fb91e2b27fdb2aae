// Reference composition of the standard model, written independently of standard.glsl:
//   f(l, v) = diffuseColor * fd + D * V * F,   L_o = f * (n.l) * E
// with F0 = lerp(0.04, baseColor, metallic), diffuseColor = baseColor * (1 - metallic)
// (seed 003), and each term evaluated by the double reference of the brick bound to its slot.
#include "common/model_reference.hpp"

namespace mb::ref {

static Vec3 evaluateStandard(const ModelEvalInput& in) {
  Vec3 baseColor = in.vec3Input("baseColor");
  double metallic = in.floatInput("metallic");
  double perceptualRoughness = in.floatInput("roughness");

  double alpha = in.callScalar("roughness", {perceptualRoughness});
  Vec3 f0 = mix(splat(0.04), baseColor, metallic);
  Vec3 diffuseColor = baseColor * (1.0 - metallic);

  double d = in.callScalar("specular_d", {}, true, {alpha});
  double v = in.callScalar("specular_v", {}, true, {alpha});
  Vec3 f = in.callVec3("fresnel", {}, true, {f0.x, f0.y, f0.z, 1.0});
  double fd = in.callScalar("diffuse", {}, true, {perceptualRoughness, alpha});

  Geometry g = makeGeometry(in.n, in.v, in.l);
  Vec3 brdf = diffuseColor * fd + f * (d * v);
  return brdf * g.NoL * in.illuminance;
}

MB_MODEL_REFERENCE("standard", evaluateStandard);

}  // namespace mb::ref
