// Kelemen visibility (Kelemen & Szirmay-Kalos 2001, "A Microfacet Based Coupled Specular-Matte
// BRDF Model with Importance Sampling"; Filament's clear-coat V; seed 000 V_Kelemen):
//   V = 1 / (4 (l.h)^2)
// Roughness is ignored. Seed 000 writes 0.25 / max((l.h)^2, 1e-5); the floor changes V for
// l.h < 3.2e-3, which the geometry domain produces (l.h = |v+l|/2 >= (n.v + n.l)/2 >= 5e-4),
// while the plain form stays finite there (<= 1e6), so it is not applied.
float mb_v_kelemen(Geometry g, float alpha) {
#ifdef MB_FP16
    // Half precision: V exceeds the largest half (65504) for l.h < 2e-3 (1e6 at the domain's
    // l.h = 5e-4) and (l.h)^2 underflows, giving Inf; clamp to 65504 as Filament's V_Kelemen
    // does with saturateMediump (surface_brdf.fs). Found by `matbricks stress --precision fp16`.
    return min(0.25 / (g.LoH * g.LoH), 65504.0);
#endif
    return 0.25 / (g.LoH * g.LoH);
}
