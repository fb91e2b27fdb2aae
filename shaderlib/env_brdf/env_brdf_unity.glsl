// Unity's environment specular BRDF (URP/built-in EnvironmentBRDFSpecular; seeds 002, 003):
//   E = surfaceReduction * lerp(f0, grazingTerm, (1 - n.v)^4)
//   surfaceReduction = 1 / (alpha^2 + 1), alpha = perceptualRoughness^2 ("not
//   perceptualRoughness"), grazingTerm = saturate(smoothness + reflectivity),
//   reflectivity = max(f0.r, f0.g, f0.b) (specular-workflow ReflectivitySpecular).
vec3 mb_env_brdf_unity(vec3 f0, float perceptualRoughness, float NoV) {
    float alpha = perceptualRoughness * perceptualRoughness;
    float surfaceReduction = 1.0 / (alpha * alpha + 1.0);
    float reflectivity = max(max(f0.r, f0.g), f0.b);
    float grazingTerm = clamp(1.0 - perceptualRoughness + reflectivity, 0.0, 1.0);
    float m = clamp(1.0 - NoV, 0.0, 1.0);
    float m2 = m * m;
    return surfaceReduction * mix(f0, vec3(grazingTerm), m2 * m2);
}
