// The rim point of SphereMaxNoH (de Carpentier 2017, Decima Engine: Advances in Lighting and
// AA; Unreal's BRDF.ush; seed 002), shared by max_noh_decima and max_noh_decima_newton: if the
// mirror ray r hits the sphere n.h = 1, else the point of the cap's rim towards r,
// l0 = l cos a + Tr, Tr = T sin a, T = unit (r - (r.l) l), and the rim's other axis
// Br = +-(r x l) sin a / |r x l|, with the sign that makes n.Br >= 0 (the source's sqrt of the
// Gram determinant |(n x l).v|, without its 1 - n.l^2 - n.v^2 - v.l^2 + 2 (n.l)(n.v)(v.l)
// cancellation). In vectors, not UE's scalars: "r inside" is |r x l| <= sin a (UE's
// r.l >= cos a rounds cos a to 1 for sin a < 2.4e-4), and T divides r - (r.l) l by |r x l|
// rather than sqrt(1 - (r.l)^2), which cancels; both carry only ~1e-7 absolute noise and T is
// scaled by sin a.
struct SphereRim {
    bool inside;     // r hits the sphere: n.h = 1
    float cosAlpha;
    vec3 tr;         // T sin a
    vec3 br;         // B sin a
};

SphereRim mb_sphere_rim(Geometry g, float sinAlpha) {
    SphereRim rim;
    vec3 r = reflect(-g.v, g.n);
    float RoL = dot(r, g.l);
    vec3 rxl = cross(r, g.l);
    float sin2RL = dot(rxl, rxl);
    rim.inside = RoL > 0.0 && sin2RL <= sinAlpha * sinAlpha;
    rim.cosAlpha = sqrt(1.0 - sinAlpha * sinAlpha);
    float rInvLengthT = sinAlpha * inversesqrt(sin2RL);  // unused when inside (may be Inf there)
    rim.tr = (r - RoL * g.l) * rInvLengthT;
    rim.br = rxl * (dot(g.n, rxl) < 0.0 ? -rInvLengthT : rInvLengthT);
    return rim;
}

// n.h at the rim point rotated by theta, tan(theta/2) = xNum / xDenom (the Newton step of
// max_noh_decima_newton; xNum = 0 is no rotation). xNum = xDenom = 0 when the rim has no
// extent (sin a = 0, e.g. v = l = n with a point light): the source's 0/0 is a NaN there; no
// rotation is the limit.
float mb_sphere_rim_noh(Geometry g, SphereRim rim, float xNum, float xDenom) {
    float den = xDenom * xDenom + xNum * xNum;
    float twoX1 = den > 0.0 ? 2.0 * xNum / den : 0.0;
    float sinTheta = twoX1 * xDenom;
    float cosTheta = 1.0 - twoX1 * xNum;
    vec3 l = g.l * rim.cosAlpha + rim.tr * cosTheta + rim.br * sinTheta;
    return clamp(dot(g.n, normalize(g.v + l)), 0.0, 1.0);
}
