// Cook-Torrance V-cavity geometric attenuation (Cook & Torrance 1982, eq. for G; Blinn 1977):
//   G = min(1, 2 n.h n.v / v.h, 2 n.h n.l / v.h),  V = G / (4 n.l n.v)
// Evaluated without 0/0: with m = min(n.l, n.v), M = max(n.l, n.v), G = min(1, 2 n.h m / v.h),
// so V = n.h / (2 v.h M) when 2 n.h m < v.h and 1 / (4 m M) otherwise; at n.l = 0 the first
// branch gives the finite limit. v.h = |v+l|/2 >= (n.v + n.l)/2 > 0 over the domain.
float mb_v_cook_torrance(Geometry g, float alpha) {
    float m = min(g.NoL, g.NoV);
    float M = max(g.NoL, g.NoV);
    if (2.0 * g.NoH * m < g.VoH) {
        return g.NoH / (2.0 * g.VoH * M);
    }
    return 0.25 / (m * M);
}
