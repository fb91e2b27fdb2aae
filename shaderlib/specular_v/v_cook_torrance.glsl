// Cook-Torrance V-cavity geometric attenuation (Cook & Torrance 1982, eq. for G; Blinn 1977):
//   G = min(1, 2 n.h n.v / v.h, 2 n.h n.l / v.h),  V = G / (4 n.l n.v)
// Evaluated without 0/0: with m = min(n.l, n.v), M = max(n.l, n.v), G = min(1, 2 n.h m / v.h),
// so V = n.h / (2 v.h M) when 2 n.h m < v.h and 1 / (4 m M) otherwise; at n.l = 0 the first
// branch gives the finite limit. v.h = |v+l|/2 >= (n.v + n.l)/2 > 0 over the domain.
float mb_v_cook_torrance(Geometry g, float alpha) {
    float m = min(g.NoL, g.NoV);
    float M = max(g.NoL, g.NoV);
#ifdef MB_FP16
    // Half precision: at grazing mirror geometry (n.v = 1e-3, n.l = 0, v.h = 5e-4) V = 1e6,
    // beyond the largest half (65504), and both branches overflow to Inf; clamp to 65504 as
    // Filament's saturateMediump does (surface_brdf.fs). Found by `matbricks stress --precision fp16`.
    float V16 = 2.0 * g.NoH * m < g.VoH ? g.NoH / (2.0 * g.VoH * M) : 0.25 / (m * M);
    return min(V16, 65504.0);
#endif
    if (2.0 * g.NoH * m < g.VoH) {
        return g.NoH / (2.0 * g.VoH * M);
    }
    return 0.25 / (m * M);
}
