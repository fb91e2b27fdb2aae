// Irradiance from the first two SH bands only (L0 + L1, 4 coefficients; Ramamoorthi &
// Hanrahan 2001 eq. 13 truncated; Sloan 2008, "Stupid Spherical Harmonics Tricks"):
//   E(n) = c4 L00 + 2 c2 (L11 x + L1-1 y + L10 z)
// Cheaper, ringing-free but blurrier than sh9_irradiance; sh4..sh8 are ignored.
vec3 mb_sh_l1_irradiance(vec3 n, vec3 sh0, vec3 sh1, vec3 sh2, vec3 sh3, vec3 sh4, vec3 sh5,
                         vec3 sh6, vec3 sh7, vec3 sh8) {
    const float c2 = 0.51166335397324424;
    const float c4 = 0.88622692545275801;
    vec3 d = normalize(n);
    return c4 * sh0 + 2.0 * c2 * (sh3 * d.x + sh1 * d.y + sh2 * d.z);
}
