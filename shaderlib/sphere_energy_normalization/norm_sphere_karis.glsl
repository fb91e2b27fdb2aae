// SphereNormalization (Karis 2013, Real Shading in UE4, eq. 14): (alpha / alpha')^2 with the
// widened alpha' = saturate(alpha + sourceRadius / (2 distance)) of UE4's
// DeferredLightingCommon (sin a = sourceRadius / distance): the ratio of GGX's 1/(pi alpha^2)
// peak normalizations, which undoes the energy the representative point adds.
float mb_norm_sphere_karis(Geometry g, float alpha, float sinAlpha) {
    float k = alpha / clamp(alpha + 0.5 * sinAlpha, 0.0, 1.0);
    return k * k;
}
