// Exact unpolarized Fresnel reflectance of a dielectric whose normal-incidence reflectance is
// f0 (Cook & Torrance 1982, eq. in sec. "Fresnel"; Walter et al. 2007 eq. 22), per channel:
//   c = v.h, eta = (1 + sqrt f0)/(1 - sqrt f0), g = sqrt(eta^2 - 1 + c^2),
//   F = 1/2 ((g - c)/(g + c))^2 (1 + ((c (g + c) - 1)/(c (g - c) + 1))^2)
// f90 is not used (the exact F reaches 1 at grazing by itself).
// Stability: eta -> inf as f0 -> 1 and g - c cancels as f0 -> 0. With s = sqrt f0, q = 1 - s
// and R = sqrt(4 s + c^2 q^2) (so that g = R / q, eta^2 - 1 = 4 s / q^2), both ratios are
// rewritten without eta:
//   (g - c)/(g + c) = 4 s / (R + c q)^2,
//   (c (g + c) - 1)/(c (g - c) + 1) = (c (R + c q) - q)(R + c q) / (4 s c + q (R + c q)),
// finite for f0 = 1 (F = 1) and with no cancellation at small f0; f0 = 0 (no interface) is
// returned as 0 explicitly (R + c q = 0 at c = 0 there).
vec3 mb_f_dielectric_exact(Geometry g, vec3 f0, float f90) {
    float c = g.VoH;
    vec3 s = sqrt(f0);
    vec3 q = vec3(1.0) - s;
    vec3 R = sqrt(4.0 * s + c * c * q * q);
    vec3 Rcq = R + c * q;
    vec3 ratioA = 4.0 * s / (Rcq * Rcq);
    vec3 ratioB = (c * Rcq - q) * Rcq / (4.0 * s * c + q * Rcq);
    vec3 F = 0.5 * ratioA * ratioA * (vec3(1.0) + ratioB * ratioB);
    return mix(F, vec3(0.0), equal(f0, vec3(0.0)));
}
