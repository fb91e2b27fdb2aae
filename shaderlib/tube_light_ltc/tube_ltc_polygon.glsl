// A tube (capsule) light's LTC integral (Heitz et al. 2016): the capsule's silhouette from the
// shading point as a polygon, each end ball's cap rim as a half 4-gon (the half away from the
// other end, stretched across the axis by pi / (4 sin(pi / 4)) so that its area is the half
// disk's) joined by the cylinder's sides, which run from +w to -w at each end, w perpendicular
// to the axis and to the end's direction. The same construction as the reference
// (common/ltc_reference.hpp, tubePolygon), vertex for vertex.
float mb_tube_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 L0, vec3 L1, float radius) {
    vec3 axis = L1 - L0;
    float axisLength = length(axis);
    const float r = 0.70710678118654752;  // cos(pi / 4)
    const vec2 half4[5] = vec2[5](vec2(1.0, 0.0), vec2(r, r), vec2(0.0, 1.0), vec2(-r, r), vec2(-1.0, 0.0));
    const float stretch = 1.11072073;  // pi / (4 sin(pi / 4))
    for (int end = 0; end < 2; ++end) {
        vec3 E = end == 0 ? L0 : L1;
        float d = length(E);
        vec3 c = d > 0.0 ? E / d : g.n;
        float sinA = mb_ltc_sin_alpha(d, radius);
        float cosA = sqrt(1.0 - sinA * sinA);
        vec3 w = cross(axis, c);
        float wl = length(w);
        vec3 e1, e2;
        mb_orthonormal_basis(c, e1, e2);
        w = wl > 1e-12 ? w / wl : e1;
        // Away from the other end; seen end-on (or with no length) the ends take opposite
        // halves, so that a zero-length tube is its sphere's disk.
        vec3 o = cross(c, w);
        float away = dot(o, end == 0 ? -axis : axis);
        if (away < -1e-9 * axisLength || (!(away > 1e-9 * axisLength) && end == 1)) o = -o;
        float side = end == 0 ? 1.0 : -1.0;
        for (int i = 0; i < 5; ++i)
            mbLtcPoly[end * 5 + i] = c * cosA + (w * (side * half4[i].x) + o * (stretch * half4[i].y)) * sinA;
    }
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, 10);
}
