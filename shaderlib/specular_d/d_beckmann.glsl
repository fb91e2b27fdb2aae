// Beckmann NDF (Beckmann & Spizzichino 1963; Walter et al. 2007 eq. 25; Cook & Torrance 1982):
//   D(h) = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h))
// Stability: tan^2 = |n x h|^2 / (n.h)^2 (no 1 - (n.h)^2 cancellation). As n.h -> 0 the
// exponential vanishes faster than cos^4, so D -> 0: the division by cos^4 is done as two
// divisions by cos^2 (cos^4 underflows first), and cos^2 == 0 returns the limit 0.
float mb_d_beckmann(Geometry g, float alpha) {
    vec3 nxh = cross(g.n, g.h);
    float sin2 = dot(nxh, nxh);
    float cos2 = g.NoH * g.NoH;
    if (cos2 == 0.0) {
        return 0.0;
    }
#ifdef MB_FP16
    // Half precision: below cos^2 = 2^-5, D < 1.2e-11 for every alpha <= 1 (exp(-31) /
    // (pi 2^-10) at alpha = 1), which rounds to 0 in half; returning it avoids a denormal
    // cos^2 (kept by some devices, 0 on others) whose reciprocal overflows: 0 * Inf = NaN
    // on an NVIDIA H100 at n.h = 5e-4 (`stress --precision fp16`, docs/fp16.md).
    if (cos2 < 0.03125) {
        return 0.0;
    }
#endif
    float a2 = alpha * alpha;
#ifdef MB_FP16
    // The divisor pi a^2 cos^4 as logarithms in the exponent: written as divisions, a compiler
    // may fold them into one product (GLSL lets it reassociate what is not `precise`), which
    // underflows in half at cos^2 < 0.36 for alpha = 0.0079 and gives 0 * Inf = NaN: an NVIDIA
    // H200's own half arithmetic did at n.h = 0.26 (docs/devices.md). The logarithms are of
    // normal numbers (cos^2 >= 2^-5 here, a^2 >= 6.3e-5 on the fp16 domain) and the sum stays
    // finite or -Inf, whatever the order.
    return exp(-sin2 / (cos2 * a2) - log(MB_PI * a2) - 2.0 * log(cos2));
#else
    return exp(-sin2 / (cos2 * a2)) / cos2 / cos2 / (MB_PI * a2);
#endif
}
