// Kelemen visibility (Kelemen & Szirmay-Kalos 2001, "A Microfacet Based Coupled Specular-Matte
// BRDF Model with Importance Sampling"; Filament's clear-coat V; seed 000 V_Kelemen):
//   V = 1 / (4 (l.h)^2)
// Roughness is ignored. Seed 000 writes 0.25 / max((l.h)^2, 1e-5); the floor changes V for
// l.h < 3.2e-3, which the geometry domain produces (l.h = |v+l|/2 >= (n.v + n.l)/2 >= 5e-4),
// while the plain form stays finite there (<= 1e6), so it is not applied.
float mb_v_kelemen(Geometry g, float alpha) {
    return 0.25 / (g.LoH * g.LoH);
}
