// SphereMaxNoH with the Newton step (de Carpentier 2017, Decima Engine: Advances in Lighting
// and AA; Unreal's BRDF.ush; seed 002): the rim point towards r (common/sphere_rim.glsl) is
// rotated on the rim by one Newton step towards the max of n.h, from the source's closed-form
// tan(theta/2), regrouped so that it does not cancel (docs/validation.md, issue 14).
float mb_max_noh_decima_newton(Geometry g, float sinAlpha) {
    SphereRim rim = mb_sphere_rim(g, sinAlpha);
    if (rim.inside) return 1.0;
    // The source's scalars, from the rim point's vectors: N0 = n.(v + l0) and D0 = 1 + v.l0,
    // where l0 = l cos a + Tr is the rim point the step starts from (the source's NoLVTr and
    // VoLVTr). D0 is |v + l0|^2 / 2: the source's VoL cos a + 1 + VoTr cancels to ~1e-7
    // absolute where l0 nears -v (grazing views, where r nears -v), which is most of D0 there.
    vec3 w = g.v + (g.l * rim.cosAlpha + rim.tr);
    float N0 = dot(g.n, w), D0 = 0.5 * dot(w, w);
    // v.Tr and v.Br from v + l (l.Tr = l.Br = 0): near v = -l, dot(v, Tr) would add the
    // ~1e-7 rounding of Tr along l, which xDenom amplifies where its terms cancel.
    vec3 u = g.v + g.l;
    float NoTr = dot(g.n, rim.tr), VoTr = dot(u, rim.tr), NoBr = dot(g.n, rim.br), VoBr = dot(u, rim.br);
    // One Newton step in x = tan(theta/2) on g = N^2 / D, N(theta) = n.(v + l(theta)),
    // D(theta) = 1 + v.l(theta): x = xNum / xDenom with xNum = -g'(0) D0^3 / 4 as in the source
    // and xDenom = g''(0) D0^3 / 2, which the source expands as p^2 + s (s - 2p) + N0 ((NoL cos a
    // + NoV) D0^2 + q (-(D0 + VoL cos a)/2 - 1/2)): O(1) products whose sum is O(sin a) (N0 and
    // D0 are themselves sums holding cos a). The same polynomial grouped by its derivatives,
    // (p - s)^2 + q (N0 VoTr / 2 - NoTr D0) with N'' = -NoTr, D'' = -VoTr, has no such
    // cancellation: what is left is the second derivative's own, which is the input
    // conditioning of the step (docs/validation.md).
    float q = N0 * D0;
    float pMinusS = NoBr * D0 - VoBr * N0;
    float xNum = q * (-0.5 * NoBr * D0 + 0.25 * VoBr * N0);
    float xDenom = pMinusS * pMinusS + q * (0.5 * N0 * VoTr - NoTr * D0);
    return mb_sphere_rim_noh(g, rim, xNum, xDenom);
}
