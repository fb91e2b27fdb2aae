// GGX / Trowbridge-Reitz NDF. Walter et al. 2007, eq. 33:
//   D(h) = alpha^2 / (pi * ((n.h)^2 (alpha^2 - 1) + 1)^2)
// The denominator is rewritten as (1 - (n.h)^2) + (n.h * alpha)^2 with 1 - (n.h)^2 taken
// as |n x h|^2 (Filament, surface_brdf.fs): at alpha = 0.045^2 the direct form cancels
// catastrophically in fp32 near n.h = 1 (~4e-3 relative error measured, docs/accuracy.md).
float mb_d_ggx(Geometry g, float alpha) {
    vec3 nxh = cross(g.n, g.h);
    float oneMinusNoH2 = dot(nxh, nxh);
    float a = g.NoH * alpha;
    float k = alpha / (oneMinusNoH2 + a * a);
    return k * k * (1.0 / MB_PI);
}
