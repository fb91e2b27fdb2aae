// SphereMaxNoH with the Newton step (de Carpentier 2017, Decima Engine: Advances in Lighting
// and AA; Unreal's BRDF.ush; seed 002): the rim point towards r (max_noh_decima) is rotated on
// the rim by one Newton step of d(n.h)/d(theta) = 0, from the source's closed-form tan(theta/2).
// The frame (T sin a, B sin a) is built from vectors as in max_noh_decima; B = +-(r x l) with
// the sign that makes n.B >= 0, which is the source's sqrt of the Gram determinant
// |(n x l).v| without its 1 - n.l^2 - n.v^2 - v.l^2 + 2 (n.l)(n.v)(v.l) cancellation.
float mb_max_noh_decima_newton(Geometry g, float sinAlpha) {
    vec3 r = reflect(-g.v, g.n);
    float RoL = dot(r, g.l);
    vec3 rxl = cross(r, g.l);
    float sin2RL = dot(rxl, rxl);
    if (RoL > 0.0 && sin2RL <= sinAlpha * sinAlpha) return 1.0;
    float cosAlpha = sqrt(1.0 - sinAlpha * sinAlpha);
    float rInvLengthT = sinAlpha * inversesqrt(sin2RL);
    vec3 tr = (r - RoL * g.l) * rInvLengthT;
    vec3 br = rxl * (dot(g.n, rxl) < 0.0 ? -rInvLengthT : rInvLengthT);
    float NoL = dot(g.n, g.l), NoV = dot(g.n, g.v), VoL = dot(g.v, g.l);
    float NoTr = dot(g.n, tr), VoTr = dot(g.v, tr), NoBr = dot(g.n, br), VoBr = dot(g.v, br);
    float NoLVTr = NoL * cosAlpha + NoV + NoTr;
    float VoLVTr = VoL * cosAlpha + 1.0 + VoTr;
    float p = NoBr * VoLVTr;
    float q = NoLVTr * VoLVTr;
    float s = VoBr * NoLVTr;
    float xNum = q * (-0.5 * p + 0.25 * VoBr * NoLVTr);
    float xDenom = p * p + s * (s - 2.0 * p) +
                   NoLVTr * ((NoL * cosAlpha + NoV) * VoLVTr * VoLVTr +
                             q * (-0.5 * (VoLVTr + VoL * cosAlpha) - 0.5));
    // xNum = xDenom = 0 when the rim has no extent (sin a = 0, e.g. v = l = n with a point
    // light): the source's 0/0 is a NaN there; no rotation is the limit.
    float den = xDenom * xDenom + xNum * xNum;
    float twoX1 = den > 0.0 ? 2.0 * xNum / den : 0.0;
    float sinTheta = twoX1 * xDenom;
    float cosTheta = 1.0 - twoX1 * xNum;
    vec3 l = g.l * cosAlpha + tr * cosTheta + br * sinTheta;
    return clamp(dot(g.n, normalize(g.v + l)), 0.0, 1.0);
}
