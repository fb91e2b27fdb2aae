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
    float a2 = alpha * alpha;
    return exp(-sin2 / (cos2 * a2)) / cos2 / cos2 / (MB_PI * a2);
}
