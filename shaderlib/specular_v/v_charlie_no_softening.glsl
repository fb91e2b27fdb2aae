// Charlie sheen visibility without terminator softening (Estevez & Kulla 2017, sec. 3; seed
// 000 V_Charlie_No_Softening; Unity HDRP uses it for its sheen DFG):
//   V = 1 / ((1 + Lambda(v) + Lambda(l)) 4 n.v n.l),  Lambda = exp(ln Lambda fit)
// (common/sheen.glsl). alpha is the sheen roughness r. Domain n.l >= 1e-3: the fitted
// Lambda is finite at cos = 0, so V has a 1/n.l pole there (see v_charlie).
float mb_v_charlie_no_softening(Geometry g, float alpha) {
    float r = clamp(alpha, 0.0, 1.0);
    float lambdaV = exp(mb_sheen_charlie_log_lambda(g.NoV, r));
    float lambdaL = exp(mb_sheen_charlie_log_lambda(g.NoL, r));
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
