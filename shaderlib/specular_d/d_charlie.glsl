// "Charlie" sheen NDF (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF",
// eq. 2; seeds 000 and 004):
//   D(h) = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi)
// Stability: sin^2(theta_h) = |n x h|^2 (1 - (n.h)^2 cancels near n.h = 1), then
// sin^(1/alpha) = (sin^2)^(1/(2 alpha)). pow(0, y > 0) = 0 is defined in GLSL, so no floor is
// needed in fp32 (Filament's max(sin2h, 2^-7) is a fp16 guard; it changes D near n.h = 1).
float mb_d_charlie(Geometry g, float alpha) {
    vec3 nxh = cross(g.n, g.h);
    float sin2 = dot(nxh, nxh);
    float invAlpha = 1.0 / alpha;
    return (2.0 + invAlpha) * pow(sin2, 0.5 * invAlpha) * (0.5 / MB_PI);
}
