// Ashikhmin velvet ("inverted Gaussian") NDF (Ashikhmin & Premoze 2007, "Distribution-based
// BRDFs"; normalized form of Neubelt & Pettineo 2013, "Crafting a Next-Gen Material Pipeline
// for The Order: 1886"; seeds 000 and 004):
//   D(h) = 1 / (pi (1 + 4 alpha^2)) * (1 + 4 exp(-cot^2(theta_h) / alpha^2) / sin^4(theta_h))
// Stability: sin^2(theta_h) = |n x h|^2 (1 - (n.h)^2 cancels near n.h = 1). At sin^2 -> 0 the
// exponential vanishes faster than sin^4, so the term's limit is 0: it is computed as
// (4 e^-x / s) / s (never forming s^2, which underflows to 0 for s < 1e-19 and would give
// 0/0), and s == 0 returns the limit. This replaces Filament's max(sin2h, 2^-7) floor (a
// fp16 guard), which is not needed in fp32.
float mb_d_ashikhmin(Geometry g, float alpha) {
    vec3 nxh = cross(g.n, g.h);
    float sin2 = dot(nxh, nxh);
    float cos2 = g.NoH * g.NoH;
    float a2 = alpha * alpha;
    float term = 0.0;
#ifdef MB_FP16
    // Half precision: below sin^2 = 2^-5 the term is < 4 e^-31 / 2^-10 = 1.4e-10 for every
    // alpha <= 1, nothing beside the 1 it is added to; skipping it avoids a denormal sin^2
    // whose reciprocal overflows (0 * Inf = NaN on an NVIDIA H100). The exponent is divided
    // by sin^2 before alpha^2, so a2 * sin2 never underflows (0 / 0 at n.h = 0).
    if (sin2 > 0.03125) {
        term = 4.0 * exp(-(cos2 / sin2) / a2) / sin2 / sin2;
    }
#else
    if (sin2 > 0.0) {
        term = 4.0 * exp(-cos2 / (a2 * sin2)) / sin2 / sin2;
    }
#endif
    return (1.0 + term) / (MB_PI * (1.0 + 4.0 * a2));
}
