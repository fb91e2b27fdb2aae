// SphereHorizonCosWrap, accurate form (Unreal Engine 4, CapsuleLight.ush; seed 002): exact
// irradiance of a sphere light crossing the horizon over that of a facing point light
// (Snyder 1996). With s = sin a, c = cos a, z = sqrt(s^2 - n.l^2) / s and w = z s / c, the
// source's  n.l acos(y) - x z + atan(z/x) / s^2  is rewritten as
//   n.l atan(z s, -c n.l) + w + (atan(w) - w) / s^2
// because -x z and atan(z/x)/s^2 are each ~1/s and cancel to ~s: in fp32 the direct form loses
// ~1e-7/s absolute (1e-4 at s = 1e-3). atan(w) - w uses its odd series below w = 0.5 (no
// cancellation); acos(y) near y = 1 (lower edge) becomes an atan2 of well-conditioned terms.
float mb_horizon_wrap_accurate(Geometry g, float sinAlpha) {
    float NoL = dot(g.n, g.l);
    if (NoL >= sinAlpha) return NoL;
    if (NoL <= -sinAlpha) return 0.0;
    float s = sinAlpha;
    float c = sqrt(1.0 - s * s);
    float z = sqrt((s - NoL) * (s + NoL)) / s;
    float w = z * s / c;
    float atanMinusW;
    if (w < 0.5) {
        // atan(w) - w = -w^3 (1/3 - q/5 + q^2/7 - ...), q = w^2; 12 terms: < 1e-8 relative.
        float q = w * w;
        float p = 1.0 / 25.0;
        for (int k = 11; k >= 1; --k) p = 1.0 / float(2 * k + 1) - q * p;
        atanMinusW = -w * q * p;
    } else {
        atanMinusW = atan(w) - w;
    }
#ifdef MB_FP16
    // Half precision: s^2 underflows below s = 2.4e-4 (smallest half subnormal 6e-8) while
    // atanMinusW is already 0, and 0 / (s * s) is NaN; dividing by s twice keeps each step in
    // range. Found by `matbricks stress --precision fp16` (n.l = 0, sinAlpha = 1e-4).
    return (NoL * atan(z * s, -c * NoL) + w + atanMinusW / s / s) * (1.0 / MB_PI);
#endif
    return (NoL * atan(z * s, -c * NoL) + w + atanMinusW / (s * s)) * (1.0 / MB_PI);
}
