// Analytic DFG for GGX in the form of Lazarov's Black Ops II fit (Narkowicz 2014,
// "Analytical DFG Term for IBL", EnvDFGLazarov, after Lazarov 2013; seed 002):
//   t = gloss p0 + p1, p0 = (0.5745, 1.548, -0.02397, 1.301), p1 = (0.5753, -0.2511, -0.02066, 0.4755)
//   bias = saturate(t.x min(t.y, 2^(-7.672 n.v)) + t.z), delta = saturate(t.w)
//   E = f0 (delta - bias) + bias saturate(50 f0.g)
// gloss = 1 - perceptual roughness (Narkowicz's parameterisation).
vec3 mb_env_dfg_lazarov(vec3 f0, float perceptualRoughness, float NoV) {
    float gloss = 1.0 - perceptualRoughness;
    const vec4 p0 = vec4(0.5745, 1.548, -0.02397, 1.301);
    const vec4 p1 = vec4(0.5753, -0.2511, -0.02066, 0.4755);
    vec4 t = gloss * p0 + p1;
    float bias = clamp(t.x * min(t.y, exp2(-7.672 * NoV)) + t.z, 0.0, 1.0);
    float delta = clamp(t.w, 0.0, 1.0);
    float scale = delta - bias;
    bias *= clamp(50.0 * f0.g, 0.0, 1.0);
    return f0 * scale + bias;
}
