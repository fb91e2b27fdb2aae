// Unity's FresnelLerp for the environment specular (Unity built-in UnityStandardBRDF.cginc,
// URP; seeds 002 and 003):
//   F = lerp(f0, grazingTerm, (1 - n.v)^5),  grazingTerm = saturate(smoothness + reflectivity)
// with smoothness = 1 - perceptual roughness and reflectivity = max(f0.r, f0.g, f0.b) (URP's
// specular-workflow ReflectivitySpecular; for the metallic workflow it equals 0.04 + 0.96
// metallic when the base colour is white).
vec3 mb_f_lerp_unity(Geometry g, vec3 f0, float perceptualRoughness) {
    float reflectivity = max(max(f0.r, f0.g), f0.b);
    float grazingTerm = clamp(1.0 - perceptualRoughness + reflectivity, 0.0, 1.0);
    float t = mb_pow5(clamp(1.0 - g.NoV, 0.0, 1.0));
    return mix(f0, vec3(grazingTerm), t);
}
