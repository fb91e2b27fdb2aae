// Charlie sheen visibility with terminator softening (Estevez & Kulla 2017, "Production
// Friendly Microfacet Sheen BRDF", sec. 3 and 4; seed 000 V_Charlie):
//   V = 1 / ((1 + Lambda'(v) + Lambda'(l)) 4 n.v n.l),  Lambda' = Lambda^(1 + 2 (1 - cos)^8)
// with Lambda from the paper's fit (common/sheen.glsl). alpha is the sheen roughness r.
// Stability: Lambda^s is computed as exp(s ln Lambda) from the fitted ln Lambda (seed 000's
// pow(exp(L), s) rounds exp(L) first). The fit is finite at cos = 0 (Lambda(0) = e^20.5), so V
// has a 1/n.l pole there: the domain starts at n.l = 1e-3 (the exact V stays finite because
// the exact Lambda grows like 1/cos). (1 - cos)^8 by squaring, not pow(): n.v can exceed 1
// by an ulp and pow() of a negative base is undefined.
float mb_v_charlie_pow8(float x) {
    float x2 = x * x;
    float x4 = x2 * x2;
    return x4 * x4;
}

float mb_v_charlie(Geometry g, float alpha) {
    float r = clamp(alpha, 0.0, 1.0);
    float sv = 1.0 + 2.0 * mb_v_charlie_pow8(1.0 - g.NoV);
    float sl = 1.0 + 2.0 * mb_v_charlie_pow8(1.0 - g.NoL);
    float lambdaV = exp(sv * mb_sheen_charlie_log_lambda(g.NoV, r));
    float lambdaL = exp(sl * mb_sheen_charlie_log_lambda(g.NoL, r));
#ifdef MB_FP16
    // Half precision: 4 n.v n.l underflows (4e-6 at n.v = n.l = 1e-3: a denormal whose
    // reciprocal overflows, although V = 2e-5 there) and 1 + lambdaV + lambdaL overflows at
    // grazing angles, so (Inf * 0) gave NaN. Each factor is divided out in turn, n.l is
    // floored at the smallest normal half (2^-14; it only changes n.l < 6.1e-5) and V is
    // clamped with Filament's saturateMediump (min(x, 65504)).
    float nl = max(g.NoL, 0.00006103515625);
    return min(1.0 / (1.0 + lambdaV + lambdaL) / (4.0 * g.NoV) / nl, 65504.0);
#endif
    return 1.0 / ((1.0 + lambdaV + lambdaL) * (4.0 * g.NoV * g.NoL));
}
