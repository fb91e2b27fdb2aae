// The Newton step of SphereMaxNoH in the source's scalar expansion (de Carpentier 2017; UE4
// BRDF.ush SphereMaxNoH with bNewtonIteration; seed 002), on the same rim frame as
// max_noh_decima_newton.glsl. Kept only to show why that brick regroups the step: at grazing
// views 1 + VoL cos a + VoTr cancels (the rim point nears -v) and xDenom's O(1) products
// cancel to its O(sin a) value, so the Newton angle loses most of its fp32 digits.
float mb_max_noh_decima_newton(Geometry g, float sinAlpha) {
    SphereRim rim = mb_sphere_rim(g, sinAlpha);
    if (rim.inside) return 1.0;
    float NoL = dot(g.n, g.l), NoV = dot(g.n, g.v), VoL = dot(g.v, g.l), cosAlpha = rim.cosAlpha;
    float NoTr = dot(g.n, rim.tr), VoTr = dot(g.v, rim.tr), NoBr = dot(g.n, rim.br), VoBr = dot(g.v, rim.br);
    float NoLVTr = NoL * cosAlpha + NoV + NoTr;
    float VoLVTr = VoL * cosAlpha + 1.0 + VoTr;
    float p = NoBr * VoLVTr;
    float q = NoLVTr * VoLVTr;
    float s = VoBr * NoLVTr;
    float xNum = q * (-0.5 * p + 0.25 * VoBr * NoLVTr);
    float xDenom = p * p + s * (s - 2.0 * p) +
                   NoLVTr * ((NoL * cosAlpha + NoV) * VoLVTr * VoLVTr +
                             q * (-0.5 * (VoLVTr + VoL * cosAlpha) - 0.5));
    return mb_sphere_rim_noh(g, rim, xNum, xDenom);
}
