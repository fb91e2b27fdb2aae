// SphereMaxNoH without the Newton step (de Carpentier 2017, Decima Engine: Advances in
// Lighting and AA; Unreal's BRDF.ush; seed 002): n.h at the point of the cap's rim towards the
// mirror ray, 1 if the mirror ray hits the sphere (common/sphere_rim.glsl).
float mb_max_noh_decima(Geometry g, float sinAlpha) {
    SphereRim rim = mb_sphere_rim(g, sinAlpha);
    if (rim.inside) return 1.0;
    return clamp(dot(g.n, normalize(g.v + g.l * rim.cosAlpha + rim.tr)), 0.0, 1.0);
}
