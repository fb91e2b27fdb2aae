// Separable Schlick-GGX visibility with the IBL k = alpha / 2 (Karis 2013, "Real Shading in
// Unreal Engine 4", p. 3 and the split-sum integration; seed 003 "k_IBL"):
//   G1(x) = n.x / (n.x (1 - k) + k),  V = G1(l) G1(v) / (4 n.l n.v)
// evaluated with the n.l n.v cancelled analytically: V = 0.25 / ((n.l(1-k)+k)(n.v(1-k)+k)).
// Finite at n.l = 0 without an epsilon. k >= alpha/2 > 0 over the domain.
float mb_v_schlick_ggx_ibl(Geometry g, float alpha) {
    float k = 0.5 * alpha;
    float gl = g.NoL * (1.0 - k) + k;
    float gv = g.NoV * (1.0 - k) + k;
#ifdef MB_FP16
    // Half precision: at n.l = 0 and grazing n.v, gl * gv (2e-5 at alpha = 0.089^2) is a
    // denormal whose reciprocal overflows, although V (12735) is in range. Dividing by each
    // factor in turn is the same number in real arithmetic; gl, gv >= alpha / 2 >= 2^-8.
    return 0.25 / gl / gv;
#endif
    return 0.25 / (gl * gv);
}
