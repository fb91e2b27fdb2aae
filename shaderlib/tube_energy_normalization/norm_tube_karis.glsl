// Tube light energy normalization (Karis 2013, Real Shading in UE4, eq. 17, times eq. 14):
// the line widens the lobe in one direction only, so its factor is the ratio of the
// anisotropic GGX normalizations 1 / (pi alpha_x alpha_y) with one alpha widened,
//   LineNormalization = alpha / alpha'_line,
//   alpha'_line = saturate(alpha + 0.5 saturate(sourceLength / distance))
// (UE4 AreaLightSpecular: `LineAngle = saturate(SourceLength * InvDist)` before the widening;
// a tube longer than its distance widens the lobe by at most 0.5),
// and the tube's radius widens it in both, SphereNormalization = (alpha / alpha'_sphere)^2 with
// alpha'_sphere = saturate(alpha + sourceRadius / (2 distance)) as norm_sphere_karis. The tube's
// factor is their product. distance is to the tube's centre (L0 + L1) / 2.
float mb_norm_tube_karis(Geometry g, float alpha, vec3 L0, vec3 L1, float sourceRadius) {
    float invDistance = inversesqrt(dot(L0 + L1, L0 + L1)) * 2.0;
    float lineAngle = clamp(length(L1 - L0) * invDistance, 0.0, 1.0);
    float kLine = alpha / clamp(alpha + 0.5 * lineAngle, 0.0, 1.0);
    float kSphere = alpha / clamp(alpha + 0.5 * sourceRadius * invDistance, 0.0, 1.0);
    return kLine * kSphere * kSphere;
}
