// Roughness-aware Schlick Fresnel for ambient lighting (Lagarde 2011, "Adopting a physically
// based shading model", after Fdez-Aguera; seed 000 F_SchlickRoughness):
//   F = f0 + (max(1 - r, f0) - f0) (1 - n.v)^5,  r = perceptual roughness
// The grazing reflectance is limited to 1 - r for rough surfaces. saturate(1 - n.v) as in seed
// 000 (n.v can exceed 1 by an ulp); pow5 by multiplications.
vec3 mb_f_schlick_roughness(Geometry g, vec3 f0, float perceptualRoughness) {
    float w = mb_pow5(clamp(1.0 - g.NoV, 0.0, 1.0));
    return f0 + (max(vec3(1.0 - perceptualRoughness), f0) - f0) * w;
}
