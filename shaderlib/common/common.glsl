// Shared definitions for every brick and shading model. Kept small: a brick that needs a
// helper of its own defines it in its own file under a name prefixed by its id.

#define MB_PI 3.14159265358979323846

// Smallest n.v the shading geometry lets through (Filament's MIN_N_DOT_V): grazing views
// keep finite visibility terms. The reference uses the same constant (reference.hpp).
#define MB_MIN_N_DOT_V 1e-4

// A light's radiance (per-unit-illuminance BRDF times the illuminance), clamped to the
// largest half at fp16 as Filament's saturateMediump does: at the top of the half range the
// fp16 errors of a sharp peak, or a half vector lost to rounding near v = -l, overflow to
// Inf although the exact radiance is in range (`stress --precision fp16`, docs/fp16.md).
#ifdef MB_FP16
#define MB_SATURATE_MEDIUMP(x) min(x, 65504.0)
#else
#define MB_SATURATE_MEDIUMP(x) (x)
#endif

struct Geometry {
    vec3 n;
    vec3 v;
    vec3 l;
    vec3 h;
    float NoV;
    float NoL;
    float NoH;
    float LoH;
    float VoH;
};

float mb_pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

// Builds the shading geometry from (possibly unnormalized) vectors, as a fragment shader
// does after interpolation. v = -l has no half vector: n is used, as in reference.cpp.
Geometry makeGeometry(vec3 n, vec3 v, vec3 l) {
    Geometry g;
    g.n = normalize(n);
    g.v = normalize(v);
    g.l = normalize(l);
    vec3 s = g.v + g.l;
    float len2 = dot(s, s);
    g.h = len2 > 1e-24 ? s * inversesqrt(len2) : g.n;
    g.NoV = max(dot(g.n, g.v), MB_MIN_N_DOT_V);
    g.NoL = clamp(dot(g.n, g.l), 0.0, 1.0);
    g.NoH = clamp(dot(g.n, g.h), 0.0, 1.0);
    // v.h = l.h = |v + l| / 2 for unit v and l. Taken from |v + l| rather than dot(v, h):
    // near v = -l the fp32 half vector's direction error grows as 1e-7 / |v + l| (about 1e-4
    // at grazing back-lighting, n.v = 1e-3), and dot(v, h) inherits it as an absolute error,
    // whereas |v + l| / 2 stays within ~1e-7 absolute. Same value as reference.cpp's dot(v, h).
    float halfLength = 0.5 * sqrt(len2);
    g.LoH = len2 > 1e-24 ? clamp(halfLength, 0.0, 1.0) : clamp(dot(g.l, g.h), 0.0, 1.0);
    g.VoH = len2 > 1e-24 ? clamp(halfLength, 0.0, 1.0) : clamp(dot(g.v, g.h), 0.0, 1.0);
    return g;
}
