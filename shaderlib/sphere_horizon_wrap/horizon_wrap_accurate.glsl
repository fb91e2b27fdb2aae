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
#ifdef MB_FP16
    // Half precision: (s - n.l)(s + n.l) underflows below s = 2.4e-4 (the smallest half
    // denormal is 6e-8), so z became 0 and at n.l = 0 the atan2 below got (0, 0), whose value
    // the spec leaves undefined (NaN on an NVIDIA H100). z from the ratio n.l / s is the same
    // number in real arithmetic and stays well scaled.
    float ratio = NoL / s;
    float z = sqrt((1.0 - ratio) * (1.0 + ratio));
#else
    float z = sqrt((s - NoL) * (s + NoL)) / s;
#endif
    float w = z * s / c;
    float atanMinusW;
    // (atan(w) - w) / s^2, the last term.
    float tail;
    if (w < 0.5) {
        // atan(w) - w = -w^3 (1/3 - q/5 + q^2/7 - ...), q = w^2; 12 terms: < 1e-8 relative.
        float q = w * w;
        float p = 1.0 / 25.0;
        for (int k = 11; k >= 1; --k) p = 1.0 / float(2 * k + 1) - q * p;
        atanMinusW = -w * q * p;
#ifdef MB_FP16
        // Half precision: w^3 underflows while s^2 may too (0 / 0); q / s^2 = (z / c)^2 in
        // real arithmetic, with no division by s.
        float zc = z / c;
        tail = -w * (zc * zc) * p;
#else
        tail = atanMinusW / (s * s);
#endif
    } else {
        atanMinusW = atan(w) - w;
        tail = atanMinusW / (s * s);
    }
    return (NoL * atan(z * s, -c * NoL) + w + tail) * (1.0 / MB_PI);
}
