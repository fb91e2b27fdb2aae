// Direction to the point of a tube light's segment with the smallest angle to the mirror ray r
// (the aim Karis 2013 states for the representative point; eq. 15 is the closest point to the
// line of r instead), then the sphere step of Karis eqs. 11-12 with the tube's radius.
// Along P(t) = L0 + t Ld the cosine f(t) = r.P / |P| has
//   f'(t) |P|^3 = r.(m x P(t)) = K + t M,   m = L0 x Ld,  K = r.(m x L0),  M = r.(m x Ld):
// linear in t (m x P is P rotated a right angle in the plane of the line, towards growing t).
// M < 0: the one stationary point is the maximum, t = saturate(-K / M); otherwise the maximum
// is at an end: the one whose cosine is larger. Cross products, no cancelling differences of
// dot products: when the line nearly passes through the shading point, m is small and only
// known to ~1e-7 |L0| |Ld|, but then the whole segment spans an angle of ~|m| / (|L0| |L1|),
// which bounds the direction error.
vec3 mb_tube_point_min_angle(Geometry g, vec3 L0, vec3 L1, float sourceRadius) {
    vec3 r = reflect(-g.v, g.n);
    vec3 Ld = L1 - L0;
    vec3 m = cross(L0, Ld);
    float K = dot(r, cross(m, L0));
    float M = dot(r, cross(m, Ld));
    float t;
    if (M < 0.0) {
        t = clamp(-K / M, 0.0, 1.0);
    } else {
        t = dot(r, L1) * length(L0) > dot(r, L0) * length(L1) ? 1.0 : 0.0;
    }
    vec3 p = L0 + t * Ld;
    vec3 centerToRay = dot(p, r) * r - p;
    float len = length(centerToRay);
    return normalize(p + centerToRay * (sourceRadius < len ? sourceRadius / len : 1.0));
}
