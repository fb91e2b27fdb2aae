// Karis' non-metal shortcut of EnvBRDFApprox (Karis 2014, "Physically Based Shading on
// Mobile", EnvBRDFApproxNonmetal; seed 002): "same as EnvBRDFApprox(0.04, Roughness, NoV)"
//   r = R (-1, -0.0275) + (1, 0.0425),  E = min(r.x^2, 2^(-9.28 n.v)) r.x + r.y
// f0 is ignored (assumed 4%); returned in all three channels.
vec3 mb_env_brdf_approx_nonmetal(vec3 f0, float perceptualRoughness, float NoV) {
    vec2 r = perceptualRoughness * vec2(-1.0, -0.0275) + vec2(1.0, 0.0425);
    return vec3(min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y);
}
