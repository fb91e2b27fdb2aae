// Analytic DFG for GGX by a 2D polynomial fit (Narkowicz 2014, "Analytical DFG Term for IBL",
// EnvDFGPolynomial; seed 002), x = gloss = 1 - perceptual roughness, y = n.v:
//   bias  = saturate(min(b1 x + b2 x^2, b3 + b4 y + b5 y^2 + b6 y^3))
//   delta = saturate(d0 + d1 x + d2 y + d3 x^2 + d4 x y + d5 y^2 + d6 x^3)
//   E = f0 (delta - bias) + bias saturate(50 f0.g)
// Polynomials in Horner form where they are univariate.
vec3 mb_env_dfg_polynomial(vec3 f0, float perceptualRoughness, float NoV) {
    float x = 1.0 - perceptualRoughness;
    float y = NoV;
    float bias = clamp(min(x * (-0.1688 + 1.895 * x), 0.9903 + y * (-4.853 + y * (8.404 - 5.069 * y))), 0.0, 1.0);
    float delta = clamp(0.6045 + 1.699 * x - 0.5228 * y + x * x * (-3.603 + 2.661 * x) + 1.404 * x * y + 0.1939 * y * y,
                        0.0, 1.0);
    float scale = delta - bias;
    bias *= clamp(50.0 * f0.g, 0.0, 1.0);
    return f0 * scale + bias;
}
