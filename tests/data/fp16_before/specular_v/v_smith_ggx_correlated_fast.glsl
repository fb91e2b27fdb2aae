// Fast approximation of the height-correlated Smith-GGX visibility (Hammon 2017, "PBR Diffuse
// Lighting for GGX+Smith Microsurfaces", GDC; Filament V_SmithGGXCorrelated_Fast):
//   V = 0.5 / mix(2 n.l n.v, n.l + n.v, alpha)
// The sqrt of the exact form is replaced by a linear blend in alpha. Finite at n.l = 0
// (0.5 / (alpha n.v), the exact limit is 1 / (2 alpha n.v)); all terms non-negative.
float mb_v_smith_ggx_correlated_fast(Geometry g, float alpha) {
    float denom = mix(2.0 * g.NoL * g.NoV, g.NoL + g.NoV, alpha);
    return 0.5 / denom;
}
