// n.h at Karis's representative point of a sphere light: the point of the sphere closest to the
// mirror ray (Karis 2013, Real Shading in UE4, eqs. 11-12), with everything divided by the
// distance so that l is the unit centre direction and sin a = sourceRadius / distance:
//   centerToRay = (l.r) r - l;  closest = l + centerToRay saturate(sin a / |centerToRay|).
// |centerToRay| = 0 (the ray through the centre) takes the saturate's limit 1 explicitly
// instead of 0/0.
float mb_max_noh_karis(Geometry g, float sinAlpha) {
    vec3 r = reflect(-g.v, g.n);
    vec3 centerToRay = dot(g.l, r) * r - g.l;
    float len = length(centerToRay);
    vec3 closest = g.l + centerToRay * (sinAlpha < len ? sinAlpha / len : 1.0);
    vec3 h = normalize(g.v + normalize(closest));
    return clamp(dot(g.n, h), 0.0, 1.0);
}
