// Anisotropic GGX / Trowbridge-Reitz NDF (Burley 2012, "Physically-Based Shading at Disney",
// appendix B.2; Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 85):
//   D(h) = 1 / (pi at ab E^2),  E = (t.h / at)^2 + (b.h / ab)^2 + (n.h)^2
// Stability: E is a sum of squares, so there is no 1 - (n.h)^2 cancellation near n.h = 1 (the
// tangent-plane part of h enters through t.h and b.h directly, as |n x h|^2 does in d_ggx).
// E is kept in this scaled form, which is ~1 at the peak, rather than Filament's
// D_GGX_Anisotropic rewrite a2 (a2 / |d|^2)^2 / pi with d = (ab t.h, at b.h, a2 n.h) and
// a2 = at ab: there |d|^2 = (at ab)^2 at the peak, which underflows half precision
// (6.3e-5^2 at the fp16 roughness floor at = ab = 0.089^2) and gave +Inf under `stress
// --precision fp16`. 1/E is squared after the division, so a large E underflows to D = 0
// instead of overflowing. The interpolated tangent t is orthonormalized in mb_aniso_tangent.
float mb_d_ggx_aniso(Geometry g, vec3 t, float at, float ab) {
    vec3 tangent = mb_aniso_tangent(g.n, t);
    float x = dot(tangent, g.h) / at;
    float y = dot(cross(g.n, tangent), g.h) / ab;
    float invE = 1.0 / (x * x + y * y + g.NoH * g.NoH);
    return invE * invE / (MB_PI * at * ab);
}
