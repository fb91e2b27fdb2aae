// Analytic split-sum environment BRDF for mobile (Karis 2014, "Physically Based Shading on
// Mobile", EnvBRDFApprox, after Lazarov 2013; seed 002):
//   c0 = (-1, -0.0275, -0.572, 0.022), c1 = (1, 0.0425, 1.04, -0.04), r = R c0 + c1
//   a004 = min(r.x^2, 2^(-9.28 n.v)) r.x + r.y,  AB = (-1.04, 1.04) a004 + r.zw
//   E = f0 AB.x + AB.y,  R = perceptual roughness
// Polynomial + exp2 of a bounded argument: no cancellation beyond the fit's own.
// The result is clamped at 0, not its scale and bias: the fit's bias goes below 0 at high
// roughness and n.v (-0.0024 at R = 1, n.v = 1), where the integral it fits, Int Gv Fc, is
// positive, so a black metal (f0 = 0) would reflect negative radiance. Clamping the bias
// instead added up to 0.0024 to every f0 > 0 there, mostly away from the integral (which the
// fit already overestimates at high roughness); the result clamp changes only values below 0,
// and always towards the integral.
vec3 mb_env_brdf_approx(vec3 f0, float perceptualRoughness, float NoV) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = perceptualRoughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
    vec2 AB = vec2(-1.04, 1.04) * a004 + r.zw;
    return max(f0 * AB.x + AB.y, 0.0);
}
