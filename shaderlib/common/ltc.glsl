// Linearly transformed cosines over polygonal lights (Heitz, Dupuy, Hill & Neubelt 2016,
// "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines"): the integral of the
// distribution D_M (the clamped cosine under the matrix M) over a light is the clamped
// cosine's integral over the light's polygon mapped by M^-1, which Lambert's edge sum gives in
// closed form (eq. 11; Arvo 1995). The double reference, the shapes' polygons and the measured
// error against the brute-force integral: common/ltc_reference.hpp, docs/models/lights.md.
// Needs lights.glsl (mb_orthonormal_basis, Duff et al. 2017, which the reference mirrors so
// that both orient a light's polygon alike).

// How many vertices clipping can make of the capsule's 10. A clip keeps the a vertices above the
// plane and adds one per crossing, at most 2 min(a, n - a) of them: at most 15 from 10 (a = 5),
// then 20 from 15 (a = 10). The capsule's silhouette is not convex in general (near a large end
// ball the horizon cuts it four times: measured 12 after the first clip), so the convex bound
// n + 2 does not hold. The polygon lives in two private arrays, clipped from one into the other
// and back: passing it by value (a struct or array argument) made lavapipe's JIT take 35-57 s
// per kernel.
const int MB_LTC_MAX_VERTICES = 20;
vec3 mbLtcPoly[MB_LTC_MAX_VERTICES];
vec3 mbLtcClipped[MB_LTC_MAX_VERTICES];

// Sutherland-Hodgman of mbLtcPoly[0, count) against z >= 0 into mbLtcPoly again; returns the
// new count. The plane passes through the origin, so clipping the points clips the directions
// they stand for.
int mb_ltc_clip(int count) {
    int o = 0;
    for (int i = 0; i < count; ++i) {
        vec3 p = mbLtcPoly[i];
        vec3 q = mbLtcPoly[i + 1 == count ? 0 : i + 1];
        if (p.z >= 0.0 && o < MB_LTC_MAX_VERTICES) mbLtcClipped[o++] = p;
        if ((p.z >= 0.0) != (q.z >= 0.0) && o < MB_LTC_MAX_VERTICES) mbLtcClipped[o++] = p + (q - p) * (p.z / (p.z - q.z));
    }
    for (int i = 0; i < o; ++i) mbLtcPoly[i] = mbLtcClipped[i];
    return o;
}

// Lambert's edge sum over mbLtcPoly[0, count) above z = 0, in magnitude (either winding):
// (1 / 2 pi) |sum theta_i (p_i x p_i+1).z / |p_i x p_i+1||. The angle from atan(|c|, p.q),
// accurate for the short edges of small lights where acos(p.q) loses half its digits.
float mb_ltc_edge_sum(int count) {
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 p = normalize(mbLtcPoly[i]);
        vec3 q = normalize(mbLtcPoly[i + 1 == count ? 0 : i + 1]);
        vec3 c = cross(p, q);
        float s = length(c);
        if (s > 0.0) sum += atan(s, dot(p, q)) * (c.z / s);
    }
    return abs(sum) * (0.5 / MB_PI);
}

// Int of D_M over the polygon mbLtcPoly[0, count) (points relative to the shading point, world
// space) above the horizon, for M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the table's
// frame: n = z, v in the x-z plane on the +x side (compiler/ltc). Clipped twice: to the horizon,
// where the lobe D_M stands for ends while D_M does not, then to D_M's own support
// (M^-1 w).z >= 0. Overwrites mbLtcPoly.
float mb_ltc_integrate(vec3 n, vec3 v, float m00, float m02, float m20, float m22, int count) {
    vec3 t1 = v - n * dot(n, v);
    float len = length(t1);
    vec3 t2;
    if (len > 1e-6) {
        t1 = t1 / len;
    } else {
        // v along n: the lobe is symmetric about n, any tangent serves.
        mb_orthonormal_basis(n, t1, t2);  // lights.glsl
    }
    t2 = cross(n, t1);
    for (int i = 0; i < count; ++i) {
        vec3 w = mbLtcPoly[i];
        mbLtcPoly[i] = vec3(dot(w, t1), dot(w, t2), dot(w, n));
    }
    count = mb_ltc_clip(count);
    for (int i = 0; i < count; ++i) {
        vec3 p = mbLtcPoly[i];
        mbLtcPoly[i] = vec3(m00 * p.x + m02 * p.z, p.y, m20 * p.x + m22 * p.z);
    }
    count = mb_ltc_clip(count);
    return count < 3 ? 0.0 : mb_ltc_edge_sum(count);
}

// The sine of a ball's angular radius; inside the ball the bound of the representative-point
// bricks (standard_lights.glsl's MB_AREA_LIGHT_MAX_SIN_ALPHA).
float mb_ltc_sin_alpha(float d, float radius) {
    return d > 0.0 ? min(radius / max(d, radius), 0.95) : 0.0;
}
