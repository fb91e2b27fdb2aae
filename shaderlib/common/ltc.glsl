// Linearly transformed cosines over polygonal lights (Heitz, Dupuy, Hill & Neubelt 2016,
// "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines"): the integral of the
// distribution D_M (the clamped cosine under the matrix M) over a light is the clamped
// cosine's integral over the light's polygon mapped by M^-1, which Lambert's edge sum gives in
// closed form (eq. 11; Arvo 1995). The double reference, the shapes' polygons and the measured
// error against the brute-force integral: common/ltc_reference.hpp, docs/models/lights.md.
// Needs lights.glsl (mb_orthonormal_basis, Duff et al. 2017, which the reference mirrors so
// that both orient a light's polygon alike).

// How many vertices a light's polygon can have: the capsule's hull takes at most 32 (both caps'
// 16-gons); it is convex, so each of the two clips (horizon, then D_M's support) adds at most one:
// 34; more for rounding that makes a nearly flat corner non-convex, and mb_ltc_clip drops any
// vertex beyond the last rather than write past it. The polygon lives in two private arrays,
// clipped from one into the other and back (the second also holds the capsule's candidate
// vertices): passing it by value (a struct or array argument) made lavapipe's JIT take 35-57 s
// per kernel. Their size, 40, is set by the compilers rather than the polygons:
// the loops over a polygon's vertices must stay loops. Mesa's NIR unrolls a loop that indexes a
// private array by its counter as far as the array's size allows, up to a limit: with arrays of
// 20 it unrolled every polygon loop, and lavapipe's JIT took ~7 s for one integral and ~37 s
// for a rectangle and a disk light in one kernel; Mesa's OpenGL compiler ~8 s for one. Sized 40,
// past that limit (measured: 0.2 s, 0.7 s, 0.2 s; MESA_SHADER_CACHE_DISABLE=true matbricks
// validate --brick rect_ltc_polygon, and a material --lights rect with --target glsl450), and
// hinted [[dont_unroll]] for compilers that read GL_EXT_control_flow_attributes (a compiler
// without it reads the hint as nothing).
#ifdef GL_EXT_control_flow_attributes
#extension GL_EXT_control_flow_attributes : enable
#define MB_DONT_UNROLL [[dont_unroll]]
#else
#define MB_DONT_UNROLL
#endif

const int MB_LTC_MAX_VERTICES = 40;
vec3 mbLtcPoly[MB_LTC_MAX_VERTICES];
vec3 mbLtcClipped[MB_LTC_MAX_VERTICES];

// Sutherland-Hodgman of mbLtcPoly[0, count) against side z >= 0 (side 1 or -1) into
// mbLtcClipped, mbLtcPoly unchanged; returns the new count. The plane passes through the origin,
// so clipping the points clips the directions they stand for.
int mb_ltc_clip_into(int count, float side) {
    int o = 0;
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) {
        vec3 p = mbLtcPoly[i];
        vec3 q = mbLtcPoly[i + 1 == count ? 0 : i + 1];
        float pz = side * p.z, qz = side * q.z;
        if (pz >= 0.0 && o < MB_LTC_MAX_VERTICES) mbLtcClipped[o++] = p;
        if ((pz >= 0.0) != (qz >= 0.0) && o < MB_LTC_MAX_VERTICES) mbLtcClipped[o++] = p + (q - p) * (pz / (pz - qz));
    }
    return o;
}

// mbLtcPoly[0, count) clipped to z >= 0 in place; returns the new count.
int mb_ltc_clip(int count) {
    int o = mb_ltc_clip_into(count, 1.0);
    MB_DONT_UNROLL for (int i = 0; i < o; ++i) mbLtcPoly[i] = mbLtcClipped[i];
    return o;
}

// Lambert's edge sum over mbLtcPoly[0, count) above z = 0, in magnitude (either winding):
// (1 / 2 pi) |sum theta_i (p_i x p_i+1).z / |p_i x p_i+1||. The angle from atan(|c|, p.q),
// accurate for the short edges of small lights where acos(p.q) loses half its digits.
float mb_ltc_edge_sum(int count) {
    float sum = 0.0;
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) {
        vec3 p = normalize(mbLtcPoly[i]);
        vec3 q = normalize(mbLtcPoly[i + 1 == count ? 0 : i + 1]);
        vec3 c = cross(p, q);
        float s = length(c);
        if (s > 0.0) sum += atan(s, dot(p, q)) * (c.z / s);
    }
    return abs(sum) * (0.5 / MB_PI);
}

// Moves mbLtcPoly[0, count) (points relative to the shading point, world space) into the
// table's frame, n = z and v in the x-z plane on the +x side (compiler/ltc), and clips it to the
// horizon: the lobe D_M stands for ends there, D_M does not. Returns the new count; v in that
// frame through vLocal.
int mb_ltc_to_local(vec3 n, vec3 v, int count, out vec3 vLocal) {
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
    // Unit directions from here on: a clip's new vertex is then interpolated between two unit
    // vectors, not between two far points of a large light whose edge passes near the shading
    // point, where the difference of the points would cost the direction most of its digits.
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) {
        vec3 w = mbLtcPoly[i];
        float len = length(w);
        if (len > 0.0) w = w / len;
        mbLtcPoly[i] = vec3(dot(w, t1), dot(w, t2), dot(w, n));
    }
    vLocal = vec3(dot(v, t1), dot(v, t2), dot(v, n));
    return mb_ltc_clip(count);
}

// Int of D_M over the local, horizon-clipped mbLtcPoly[0, count), for
// M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]: mapped by M^-1, clipped to D_M's support
// (M^-1 w).z >= 0, summed. Overwrites mbLtcPoly.
float mb_ltc_local_integral(float m00, float m02, float m20, float m22, int count) {
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) {
        vec3 p = mbLtcPoly[i];
        mbLtcPoly[i] = normalize(vec3(m00 * p.x + m02 * p.z, p.y, m20 * p.x + m22 * p.z));  // unit, as above
    }
    count = mb_ltc_clip(count);
    return count < 3 ? 0.0 : mb_ltc_edge_sum(count);
}

// Int of D_M over the light polygon mbLtcPoly[0, count) above the horizon. Overwrites mbLtcPoly.
float mb_ltc_integrate(vec3 n, vec3 v, float m00, float m02, float m20, float m22, int count) {
    vec3 vLocal;
    count = mb_ltc_to_local(n, v, count, vLocal);
    return mb_ltc_local_integral(m00, m02, m20, m22, count);
}

// The lobe the table was fitted to (F = 1) at the unit l of the table's frame (n = z): GGX D,
// the exact height-correlated Smith V (Heitz 2014 eq. 99) and n.l, 0 below the horizon. D from
// the unnormalized half vector H = v + l: with n = z, 1 - (n.h)^2 is (H.x^2 + H.y^2) / |H|^2
// exactly, so D = a^2 / (pi u^2) with u = (H.x^2 + H.y^2 + a^2 H.z^2) / |H|^2 has none of the
// cancellation of 1 - NoH^2 at the peak of a sharp lobe.
float mb_ltc_lobe(vec3 v, float alpha, vec3 l) {
    if (!(l.z > 0.0)) return 0.0;
    vec3 H = v + l;
    float a2 = alpha * alpha;
    float HH = dot(H, H);
    if (!(HH > 0.0)) return 0.0;  // l = -v: no half vector (and no light: l.z > 0 > v.z there)
    // u = 1 - (1 - a^2) (n.h)^2 in [a^2, 1], divided out one factor at a time: t^2 underflowed in
    // half precision where H is short (l near -v) and a^2 |H|^4 / 0 was Inf (stress, fp16).
    float u = (dot(H.xy, H.xy) + a2 * H.z * H.z) / HH;
    float D = (a2 / u) / (MB_PI * u);
    float NoV = max(v.z, MB_MIN_N_DOT_V);
    float NoL = l.z;
    // V n.l in one quotient: V alone reaches 0.5 / (n.v alpha), beyond half precision's range at
    // grazing views, and Inf - Inf in the residual was NaN (stress, fp16). The product is capped
    // at the half range, as the models cap their radiance (MB_SATURATE_MEDIUMP).
    float VNoL = 0.5 * NoL / (NoL * sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * sqrt(NoL * NoL * (1.0 - a2) + a2));
    return MB_SATURATE_MEDIUMP(D * VNoL);
}

// The sheen lobe the sheen table was fitted to (shaderlib/ltc/charlie.json; sheenColor = 1) at
// the unit l of the table's frame: Charlie D (Estevez & Kulla 2017, eq. 2) times Ashikhmin's V
// (Neubelt & Pettineo 2013) times n.l, 0 below the horizon (common/ltc_reference.hpp,
// charlieLobeLocal). sin^2(theta_h) = (H.x^2 + H.y^2) / |H|^2 of the unnormalized half vector:
// D's peak is at sin^2 = 1, where this has ~2 ulps of relative error, which the exponent
// 1 / (2 alpha) multiplies (5e-5 relative at alpha = 0.0025, the lights' roughness floor).
// log(0) is undefined in GLSL: a half vector along n gives D = 0 directly.
float mb_ltc_charlie_lobe(vec3 v, float alpha, vec3 l) {
    if (!(l.z > 0.0)) return 0.0;
    vec3 H = v + l;
    float HH = dot(H, H);
    float sin2 = HH > 0.0 ? dot(H.xy, H.xy) / HH : 0.0;
    if (!(sin2 > 0.0)) return 0.0;
    float D = (2.0 + 1.0 / alpha) * exp(log(sin2) * (0.5 / alpha)) * (0.5 / MB_PI);
    float NoV = max(v.z, MB_MIN_N_DOT_V);
    float NoL = l.z;
    return MB_SATURATE_MEDIUMP(D * NoL / (4.0 * (NoL + NoV * (1.0 - NoL))));
}

// Which lobe a control-variate integral stands for (the brick passes a constant, which the
// compiler folds after inlining).
const int MB_LTC_LOBE_GGX = 0;
const int MB_LTC_LOBE_CHARLIE = 1;

// The residual's integrand in the LTC's space (common/ltc_reference.hpp, warpedResidual) at the
// unit o: the lobe at w = M o / |M o| times the Jacobian |det M| / |M o|^3, less norm D_o(o). With
// d = m00 m22 - m02 m20, the determinant of M^-1 (positive over the tables), M o is W / d for
// W = (m22 o.x - m02 o.z, d o.y, m00 o.z - m20 o.x), so the Jacobian is d^2 / |W|^3.
float mb_ltc_warped_residual(int lobe, vec3 v, float alpha, float norm, float m00, float m02, float m20, float m22,
                             vec3 o) {
    float d = m00 * m22 - m02 * m20;
    vec3 w = vec3(m22 * o.x - m02 * o.z, d * o.y, m00 * o.z - m20 * o.x);
    float len = length(w);
    float dl = d / len;  // one factor at a time: d^2 underflows half precision at small alpha
    float f = lobe == MB_LTC_LOBE_CHARLIE ? mb_ltc_charlie_lobe(v, alpha, w / len) : mb_ltc_lobe(v, alpha, w / len);
    return f * (dl * dl / len) - norm * max(o.z, 0.0) * (1.0 / MB_PI);
}

// The residual's quadrature over mbLtcClipped[0, count), a polygon of the LTC's space: triangles
// fanned from its vertices' mean direction, each split into its four midpoint children, each
// child its solid angle (Van Oosterom & Strackee 1983) times the mean at three interior points
// (barycentric 2/3, 1/6, 1/6); common/ltc_reference.hpp, polygonSpecularWithResidual.
float mb_ltc_fan_residual(int lobe, vec3 v, float alpha, float norm, float m00, float m02, float m20, float m22,
                          int count) {
    if (count < 3) return 0.0;
    vec3 centre = vec3(0.0);
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) centre += normalize(mbLtcClipped[i]);
    centre = normalize(centre);
    float sum = 0.0;
    MB_DONT_UNROLL for (int k = 0; k < count; ++k) {
        vec3 a = centre;
        vec3 b = normalize(mbLtcClipped[k]);
        vec3 c = normalize(mbLtcClipped[k + 1 == count ? 0 : k + 1]);
        vec3 ab = normalize(a + b), bc = normalize(b + c), ca = normalize(c + a);
        // One call site in loops that stay loops: each inlined copy of the lobe costs lavapipe's
        // JIT time.
        MB_DONT_UNROLL for (int child = 0; child < 4; ++child) {
            vec3 x = child == 0 ? a : (child == 2 ? ca : ab);  // (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)
            vec3 y = child == 0 ? ab : (child == 1 ? b : bc);
            vec3 z = child == 1 ? bc : (child == 2 ? c : ca);
            float omega = 2.0 * atan(abs(dot(x, cross(y, z))), 1.0 + dot(x, y) + dot(y, z) + dot(z, x));
            float mean = 0.0;
            MB_DONT_UNROLL for (int j = 0; j < 3; ++j) {
                vec3 corner = j == 0 ? x : (j == 1 ? y : z);
                vec3 o = normalize(corner * 0.5 + (x + y + z) * (1.0 / 6.0));  // 2/3 corner + 1/6 others
                mean += mb_ltc_warped_residual(lobe, v, alpha, norm, m00, m02, m20, m22, o);
            }
            sum += omega * mean * (1.0 / 3.0);
        }
    }
    return sum;
}

// Int of the lobe (GGX with F = 1, or the sheen with sheenColor = 1) over the light polygon
// mbLtcPoly[0, count) above the horizon: norm times D_M's integral plus the residual's quadrature
// in the LTC's space, on each side of D_M's support plane (common/ltc_reference.hpp says why).
// Overwrites mbLtcPoly.
float mb_ltc_lobe_cv(int lobe, vec3 n, vec3 v, float alpha, float norm, float m00, float m02, float m20, float m22,
                     int count) {
    vec3 vLocal;
    count = mb_ltc_to_local(n, v, count, vLocal);
    if (count < 3) return 0.0;
    MB_DONT_UNROLL for (int i = 0; i < count; ++i) {
        vec3 p = mbLtcPoly[i];
        mbLtcPoly[i] = normalize(vec3(m00 * p.x + m02 * p.z, p.y, m20 * p.x + m22 * p.z));  // unit, as above
    }
    float residual = 0.0;
    int inside = 0;
    MB_DONT_UNROLL for (int part = 0; part < 2; ++part) {
        int k = mb_ltc_clip_into(count, part == 0 ? -1.0 : 1.0);
        residual += mb_ltc_fan_residual(lobe, vLocal, alpha, norm, m00, m02, m20, m22, k);
        inside = k;  // the last part is D_M's support
    }
    MB_DONT_UNROLL for (int i = 0; i < inside; ++i) mbLtcPoly[i] = mbLtcClipped[i];
    float ltc = inside < 3 ? 0.0 : mb_ltc_edge_sum(inside);
    // The integral of a non-negative lobe over part of the hemisphere lies between 0 and its
    // integral over the whole, norm: a quadrature that over- or undershoots is cut there (at
    // grazing views of smooth lobes the fit is poor and one level of splitting overshoots).
    return clamp(norm * ltc + residual, 0.0, norm);
}

// The sine of a ball's angular radius; inside the ball the bound of the representative-point
// bricks (standard_lights.glsl's MB_AREA_LIGHT_MAX_SIN_ALPHA).
float mb_ltc_sin_alpha(float d, float radius) {
    return d > 0.0 ? min(radius / max(d, radius), 0.95) : 0.0;
}

// The cap of a ball seen from the shading point as a regular k-gon (k = 8 or 16) of the disk
// that faces the point and whose rim is the cap's rim (centre c cos a, radius sin a at unit
// distance; D_M and the lobe integrate over directions, so that disk is the ball exactly, as
// Heitz & Hill 2017 shade spheres), oriented by Duff et al.'s basis about c as the reference
// (spherePolygon), its vertices at radius sin a times scale. Vertex i of k; sinA > 0.
const vec2 MB_LTC_RIM16[16] = vec2[16](
    vec2(1.0, 0.0), vec2(0.923879533, 0.382683432), vec2(0.707106781, 0.707106781), vec2(0.382683432, 0.923879533),
    vec2(0.0, 1.0), vec2(-0.382683432, 0.923879533), vec2(-0.707106781, 0.707106781), vec2(-0.923879533, 0.382683432),
    vec2(-1.0, 0.0), vec2(-0.923879533, -0.382683432), vec2(-0.707106781, -0.707106781),
    vec2(-0.382683432, -0.923879533), vec2(0.0, -1.0), vec2(0.382683432, -0.923879533),
    vec2(0.707106781, -0.707106781), vec2(0.923879533, -0.382683432));  // (cos, sin)(2 pi i / 16)
vec3 mb_ltc_cap_vertex(vec3 n, vec3 toCenter, float sinA, float scale, int i, int k) {
    float d = length(toCenter);
    vec3 c = d > 0.0 ? toCenter / d : n;
    float cosA = sqrt(1.0 - sinA * sinA);
    vec3 e1, e2;
    mb_orthonormal_basis(c, e1, e2);
    vec2 rim = MB_LTC_RIM16[i * (16 / k)];
    float s = sinA * scale;
    return c * cosA + (e2 * rim.x + e1 * rim.y) * s;
}

// The sphere light: its cap's 8-gon of the disk's area. Fills mbLtcPoly; returns its count (0 for a point light,
// which has no solid angle).
int mb_ltc_sphere_polygon(vec3 n, vec3 toCenter, float radius) {
    float sinA = mb_ltc_sin_alpha(length(toCenter), radius);
    if (!(sinA > 0.0)) return 0;
    for (int i = 0; i < 8; ++i) mbLtcPoly[i] = mb_ltc_cap_vertex(n, toCenter, sinA, 1.05390926, i, 8);  // sqrt(2 pi / (8 sin(pi / 4)))
    return 8;
}

// A rectangle (parallelogram) light: centre c, half-edge vectors ex and ey, emitting on the side
// ex x ey points to; from behind or edge-on it sends nothing (count 0). Exactly the light's
// polygon (common/ltc_reference.hpp, rectPolygon). Fills mbLtcPoly; returns its count.
int mb_ltc_rect_polygon(vec3 c, vec3 ex, vec3 ey) {
    if (!(dot(cross(ex, ey), c) < 0.0)) return 0;
    mbLtcPoly[0] = c - ex - ey;
    mbLtcPoly[1] = c + ex - ey;
    mbLtcPoly[2] = c + ex + ey;
    mbLtcPoly[3] = c - ex + ey;
    return 4;
}

// A disk (ellipse) light: centre c, semi-axis vectors ex and ey, one-sided as the rectangle; the
// regular 8-gon of the ellipse's area, c + (ex cos phi_i + ey sin phi_i) sqrt(2 pi / (8 sin(pi / 4)))
// (diskPolygon). Fills mbLtcPoly; returns its count.
int mb_ltc_disk_polygon(vec3 c, vec3 ex, vec3 ey) {
    if (!(dot(cross(ex, ey), c) < 0.0)) return 0;
    for (int i = 0; i < 8; ++i) mbLtcPoly[i] = c + (ex * MB_LTC_RIM16[2 * i].x + ey * MB_LTC_RIM16[2 * i].y) * 1.05390926;
    return 8;
}

// The tube (capsule) light's silhouette from the shading point: the spherical convex hull of its
// two end caps' 16-gons (of the circle's mean width), by gift wrapping on the sphere (Jarvis
// 1973): from the vertex farthest against e1 of the ends' mean direction, each next vertex is the
// one that leaves every other on the left of the great circle through both. Continuous as the
// ends move, end-on views included (common/ltc_reference.hpp, tubePolygon, which this follows
// step for step). The candidates sit in mbLtcClipped and are read only at loop indices, vertices
// carried by value: reads at a computed index made lavapipe's JIT take ~60 s; the loops stay
// loops (32 x 32 unrolled would be 1024 copies). Fills mbLtcPoly; returns its count, at most 32.
int mb_ltc_tube_polygon(vec3 n, vec3 L0, vec3 L1, float radius) {
    float d0 = length(L0), d1 = length(L1);
    float sin0 = mb_ltc_sin_alpha(d0, radius), sin1 = mb_ltc_sin_alpha(d1, radius);
    if (!(sin0 > 0.0) || !(sin1 > 0.0)) return 0;  // no radius: a line has no solid angle
    MB_DONT_UNROLL for (int i = 0; i < 16; ++i) {
        // The 16-gons of the circle's mean width, pi / (16 sin(pi / 16)): the sides take their
        // width from them (tubePolygon).
        mbLtcClipped[i] = mb_ltc_cap_vertex(n, L0, sin0, 1.00645454, i, 16);
        mbLtcClipped[16 + i] = mb_ltc_cap_vertex(n, L1, sin1, 1.00645454, i, 16);
    }
    vec3 mid = (d0 > 0.0 ? L0 / d0 : n) + (d1 > 0.0 ? L1 / d1 : n);
    vec3 m = length(mid) > 0.0 ? normalize(mid) : n;
    vec3 e1, e2;
    mb_orthonormal_basis(m, e1, e2);
    int cur = 0;
    MB_DONT_UNROLL for (int j = 1; j < 32; ++j)
        if (dot(normalize(mbLtcClipped[j]), e1) < dot(normalize(mbLtcClipped[cur]), e1)) cur = j;
    vec3 p = mbLtcClipped[cur];
    uint seen = 0u;
    int count = 0;
    MB_DONT_UNROLL for (int step = 0; step < 32; ++step) {
        mbLtcPoly[step] = p;
        count = step + 1;
        seen |= 1u << uint(cur);
        int next = -1;
        vec3 best = p;
        MB_DONT_UNROLL for (int j = 0; j < 32; ++j) {
            vec3 q = mbLtcClipped[j];
            if (q == p) continue;
            if (next < 0) {
                next = j;
                best = q;
                continue;
            }
            // q right of p -> best is the better next (a q on that great circle leaves the hull's
            // area as it is, either way). The determinant [p, best, q] from the differences: the
            // vertices of one small cap are close together, and cross(p, best) of two of them has
            // lost most of its digits (fp32 wrapped in circles on thin tubes).
            if (dot(p, cross(best - p, q - p)) < 0.0) {
                next = j;
                best = q;
            }
        }
        // Back at a vertex taken already: closed (at the start) or, where rounding made the
        // choices inconsistent on a nearly degenerate hull, stopped rather than looping.
        if (next < 0 || (seen & (1u << uint(next))) != 0u) break;
        cur = next;
        p = best;
    }
    return count;
}
