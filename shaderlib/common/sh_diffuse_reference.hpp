// Reference of common/sh_diffuse.glsl, the models' Lambertian diffuse of the SH9 environment,
// in double: diffuseColor * max(E(n), 0) / pi * ao, E the bound sh_irradiance brick's
// reference at the shading normal and the environment's SH9 radiance.
#pragma once
#include "common/model_reference.hpp"

namespace mb::ref {

// Irradiance E(n) of the SH9 radiance, clamped at 0 (a truncated expansion rings below it;
// Filament clamps too); a Lambertian surface reflects E / pi.
inline Vec3 shDiffuse(const ModelEvalInput& in, const Vec3& diffuseColor, const Environment& env, double ao) {
  Args sh = Args() << in.frame.n;
  for (const Vec3& c : env.sh) sh << c;
  return diffuseColor * nonNegative(in.vec3("sh_irradiance", sh)) * (ao / kPi);
}

}  // namespace mb::ref
