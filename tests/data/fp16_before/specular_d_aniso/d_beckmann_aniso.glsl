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
    vec3 tangent = mb_aniso_tangent(g.n, t);
    float x = dot(tangent, g.h) / at;
    float y = dot(cross(g.n, tangent), g.h) / ab;
    return exp(-(x * x + y * y) / cos2) / cos2 / cos2 / (MB_PI * at * ab);
}
