// Fast approximation of the height-correlated Smith-GGX visibility (Hammon 2017, "PBR Diffuse
// Lighting for GGX+Smith Microsurfaces", GDC; Filament V_SmithGGXCorrelated_Fast):
//   V = 0.5 / mix(2 n.l n.v, n.l + n.v, alpha)
// The sqrt of the exact form is replaced by a linear blend in alpha. Finite at n.l = 0
// (0.5 / (alpha n.v), the exact limit is 1 / (2 alpha n.v)); all terms non-negative.
float mb_v_smith_ggx_correlated_fast(Geometry g, float alpha) {
    float denom = mix(2.0 * g.NoL * g.NoV, g.NoL + g.NoV, alpha);
#ifdef MB_FP16
    // Half precision: at n.l = 0 the denominator alpha n.v is a denormal from n.v < 7.7e-3 at
    // alpha = 0.089^2; its reciprocal overflows to Inf although V (63291 at n.v = 1e-3) is in
    // range (an NVIDIA H100 gave Inf). Filament's V_SmithGGXCorrelated_Fast clamps V with
    // saturateMediump (min(x, 65504)) for the same reason.
    return min(0.5 / denom, 65504.0);
#endif
    return 0.5 / denom;
}
