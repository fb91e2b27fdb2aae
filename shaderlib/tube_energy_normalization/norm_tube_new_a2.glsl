// UE4 EnergyNormalization (ShadingModels.ush; seed 002) for a capsule, sphere and line terms:
//   New_a2(a2, s, VoH) = a2 + 0.25 s (3 sqrt(a2) + s) / (VoH + 0.001),
//   Sphere_a2 = New_a2(a2, SphereSinAlpha, VoH),  Energy = a2 / Sphere_a2,
//   LineTanAlpha = sqrt((1.0001 - LineCosSubtended) / (1 + LineCosSubtended)),
//   Line_a2 = New_a2(Sphere_a2, LineTanAlpha, VoH),  Energy *= sqrt(Sphere_a2 / Line_a2),
// with SphereSinAlpha = sourceRadius / distance (to the centre), LineCosSubtended the cosine of
// the angle between L0 and L1 (LineCosTwoAlpha: the segment subtends 2 alpha), and v.h of the
// shading geometry (g.l: the representative direction). The source skips each term when its
// light has none (SinAlpha = 0: New_a2 returns a2 anyway; LineCos = 1: a sphere light); this
// slot is for tubes, so the line term always applies, which keeps the brick continuous where
// L0 and L1 are parallel (the 1.0001 leaves tan = 0.0071 there).
// Stability: 1 - cos is taken as |u0 - u1|^2 / 2 of the unit endpoint directions, not from the
// rounded cosine (which loses everything below 6e-8 and ~1e-7 / (1 - cos) relative above);
// 1 + cos = 2 - (1 - cos).
float mb_norm_tube_new_a2_new_a2(float a2, float sinAlpha, float VoH) {
    return a2 + 0.25 * sinAlpha * (3.0 * sqrt(a2) + sinAlpha) / (VoH + 0.001);
}

float mb_norm_tube_new_a2(Geometry g, float alpha, vec3 L0, vec3 L1, float sourceRadius) {
    float a2 = alpha * alpha;
    float sinAlpha = sourceRadius * 2.0 * inversesqrt(dot(L0 + L1, L0 + L1));
    float sphereA2 = mb_norm_tube_new_a2_new_a2(a2, sinAlpha, g.VoH);
    vec3 d = normalize(L0) - normalize(L1);
    float oneMinusCos = 0.5 * dot(d, d);
    float lineTanAlpha = sqrt((oneMinusCos + 0.0001) / (2.0 - oneMinusCos));
    float lineA2 = mb_norm_tube_new_a2_new_a2(sphereA2, lineTanAlpha, g.VoH);
    return a2 / sphereA2 * sqrt(sphereA2 / lineA2);
}
