// SphereMaxNoH without the Newton step (de Carpentier 2017, Decima Engine: Advances in
// Lighting and AA; Unreal's BRDF.ush; seed 002): if the mirror ray r hits the sphere n.h = 1,
// else the point of the cap's rim towards r, l' = l cos a + T sin a, T = unit (r - (r.l) l).
// In vectors, not UE's scalars: "r inside" is |r x l| <= sin a (UE's r.l >= cos a rounds cos a
// to 1 for sin a < 2.4e-4), and T divides r - (r.l) l by |r x l| rather than sqrt(1 - (r.l)^2),
// which cancels; both carry only ~1e-7 absolute noise and T is scaled by sin a.
float mb_max_noh_decima(Geometry g, float sinAlpha) {
    vec3 r = reflect(-g.v, g.n);
    float RoL = dot(r, g.l);
    vec3 rxl = cross(r, g.l);
    float sin2RL = dot(rxl, rxl);
    if (RoL > 0.0 && sin2RL <= sinAlpha * sinAlpha) return 1.0;
    float cosAlpha = sqrt(1.0 - sinAlpha * sinAlpha);
    vec3 l = g.l * cosAlpha + (r - RoL * g.l) * (sinAlpha * inversesqrt(sin2RL));
    return clamp(dot(g.n, normalize(g.v + l)), 0.0, 1.0);
}
