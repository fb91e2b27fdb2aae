// Unity's FresnelLerpFast: the pow4 variant of FresnelLerp ("approximage Schlick with ^4
// instead of ^5", UnityStandardBRDF.cginc; URP uses Pow4(1 - n.v) as fresnelTerm; seeds 002,
// 003): F = lerp(f0, grazingTerm, (1 - n.v)^4), grazingTerm as in f_lerp_unity.
vec3 mb_f_lerp_fast_unity(Geometry g, vec3 f0, float perceptualRoughness) {
    float reflectivity = max(max(f0.r, f0.g), f0.b);
    float grazingTerm = clamp(1.0 - perceptualRoughness + reflectivity, 0.0, 1.0);
    float m = clamp(1.0 - g.NoV, 0.0, 1.0);
    float m2 = m * m;
    return mix(f0, vec3(grazingTerm), m2 * m2);
}
