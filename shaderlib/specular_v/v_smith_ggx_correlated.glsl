// Height-correlated Smith visibility for GGX (Heitz 2014, "Understanding the Masking-
// Shadowing Function in Microfacet-Based BRDFs", eq. 99; Lagarde & de Rousiers 2014,
// listing 2; seed 000 V_SmithGGX):
//   V = G2 / (4 n.l n.v) = 0.5 / (n.l sqrt(n.v^2 (1 - a^2) + a^2) + n.v sqrt(n.l^2 (1 - a^2) + a^2))
// The 4 n.l n.v of the denominator is cancelled analytically against the Lambda terms, so
// the form is finite at n.l = 0 (V -> 1 / (2 alpha n.v)) with no 0/0 and no epsilon: seed
// 000's max(..., 1e-5) guard is unnecessary because n.v >= MB_MIN_N_DOT_V and alpha > 0.
// All terms are non-negative sums: no cancellation.
float mb_v_smith_ggx_correlated(Geometry g, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = g.NoL * sqrt(g.NoV * g.NoV * (1.0 - a2) + a2);
    float lambdaL = g.NoV * sqrt(g.NoL * g.NoL * (1.0 - a2) + a2);
    float v = 0.5 / (lambdaV + lambdaL);
#ifdef MB_FP16
    // Filament's saturateMediump (surface_brdf.fs V_SmithGGXCorrelated): at fp16, n.l = 0 with
    // a clamped n.v and a small alpha (a clear coat seen from below its geometric horizon)
    // leaves a subnormal denominator, and 0.5 / it overflows to Inf, which times n.l = 0 is NaN.
    v = min(v, 65504.0);
#endif
    return v;
}
