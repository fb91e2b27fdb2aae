// A sphere light's LTC integral (Heitz et al. 2016): the sphere seen from the shading point is
// its cap, whose rim is the rim of the disk that faces the point at unit distance (centre
// c cos a, radius sin a); D_M integrates over directions, so that disk stands for the sphere
// exactly (Heitz & Hill 2017 shade spheres as facing disks). The disk becomes the regular 8-gon
// of the same area (radius x sqrt(2 pi / (8 sin(pi / 4)))), oriented by Duff et al.'s basis
// about c as the reference is.
float mb_sphere_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 toCenter, float radius) {
    float d = length(toCenter);
    vec3 c = d > 0.0 ? toCenter / d : g.n;
    float sinA = mb_ltc_sin_alpha(d, radius);
    float cosA = sqrt(1.0 - sinA * sinA);
    vec3 e1, e2;
    mb_orthonormal_basis(c, e1, e2);
    const float r = 0.70710678118654752;  // cos(pi / 4)
    const vec2 rim[8] = vec2[8](vec2(1.0, 0.0), vec2(r, r), vec2(0.0, 1.0), vec2(-r, r), vec2(-1.0, 0.0), vec2(-r, -r),
                                vec2(0.0, -1.0), vec2(r, -r));
    float s = sinA * 1.05390926;  // the 8-gon's area scale
    for (int i = 0; i < 8; ++i) mbLtcPoly[i] = c * cosA + (e2 * rim[i].x + e1 * rim[i].y) * s;
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, 8);
}
