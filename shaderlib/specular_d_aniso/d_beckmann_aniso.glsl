// Anisotropic Beckmann NDF (Beckmann & Spizzichino 1963; Ward 1992, "Measuring and Modeling
// Anisotropic Reflection", eq. 5a; Heitz 2014 eq. 84):
//   D(h) = exp(-tan^2(theta_h) (cos^2(phi_h)/at^2 + sin^2(phi_h)/ab^2)) / (pi at ab cos^4(theta_h))
// The exponent is written ((t.h / at)^2 + (b.h / ab)^2) / (n.h)^2: a sum of squares, so no
// 1 - (n.h)^2 cancellation near n.h = 1. As n.h -> 0 the exponential vanishes faster than
// cos^4, so D -> 0: the division by cos^4 is done as two divisions by cos^2 after the
// exponential (which is already 0 there), and cos^2 == 0 returns the limit 0.
float mb_d_beckmann_aniso(Geometry g, vec3 t, float at, float ab) {
    float cos2 = g.NoH * g.NoH;
    if (cos2 == 0.0) {
        return 0.0;
    }
#ifdef MB_FP16
    // Half precision: below cos^2 = 2^-5, D < 1.5e-9 for every at, ab in [0.089^2, 1]
    // (exp(-31) / (pi at ab 2^-10) with the larger alpha 1 along h), which rounds to 0 in
    // half; returning it avoids a denormal cos^2 whose reciprocal overflows (0 * Inf = NaN on
    // an NVIDIA H100, docs/fp16.md).
    if (cos2 < 0.03125) {
        return 0.0;
    }
#endif
    vec3 tangent = mb_aniso_tangent(g.n, t);
    float x = dot(tangent, g.h) / at;
    float y = dot(cross(g.n, tangent), g.h) / ab;
#ifdef MB_FP16
    // The divisor as logarithms in the exponent, so that no reassociation of the divisions can
    // underflow it to 0 in half (d_beckmann.glsl, docs/devices.md).
    return exp(-(x * x + y * y) / cos2 - log(MB_PI * at * ab) - 2.0 * log(cos2));
#else
    return exp(-(x * x + y * y) / cos2) / cos2 / cos2 / (MB_PI * at * ab);
#endif
}
