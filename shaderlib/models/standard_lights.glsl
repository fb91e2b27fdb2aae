// Standard model, lights part: point, spot, sphere and tube lights (seed 002 "Lighting model"
// and "Area lights", after Karis 2013, Real Shading in Unreal Engine 4). Each light becomes the
// BRDF of one light direction (mb_standard_light, standard.glsl) times an illuminance; the
// area lights add a representative direction for D, an energy normalization on D and a
// horizon-wrapped cosine. Conventions and their known errors: docs/models/lights.md.

#if defined(MB_LIGHT_POINT) || defined(MB_LIGHT_SPOT)
// A punctual light of direction g.l and illuminance E at the surface (facing the light).
vec3 mb_shade_punctual(ShadingPixel px, ShadingFrame f, Geometry g, vec3 illuminance) {
    return MB_SATURATE_MEDIUMP(mb_standard_light(px, f, g, g, 1.0, g.NoL, g.NoL) * illuminance);
}
#endif

#ifdef MB_LIGHT_POINT
// E = I * falloff(d): seed 002's windowed inverse square, whichever light_falloff brick is bound.
vec3 mb_shade_point(ShadingPixel px, ShadingFrame f, PointLight light) {
    Geometry g = makeGeometry(f.n, f.v, light.toLight);
    float falloff = MB_SLOT_light_falloff(light.toLight, light.falloffRadius);
    return mb_shade_punctual(px, f, g, light.intensity * falloff);
}
#endif

#ifdef MB_LIGHT_SPOT
// The point light times Filament's smooth cone (lights.glsl), applied to the illuminance.
vec3 mb_shade_spot(ShadingPixel px, ShadingFrame f, SpotLight light) {
    Geometry g = makeGeometry(f.n, f.v, light.toLight);
    float falloff = MB_SLOT_light_falloff(light.toLight, light.falloffRadius);
    float cone = mb_spot_attenuation(g.l, light.axis, light.cosOuter, light.cosInner);
    return mb_shade_punctual(px, f, g, light.intensity * (falloff * cone));
}
#endif

#if defined(MB_LIGHT_SPHERE) || defined(MB_LIGHT_TUBE)
// The sphere light bricks are declared for sin(alpha) <= 0.95 (their slot.json domains); a
// shading point nearer than radius / 0.95 to the centre (on or inside the light, where the
// representative-point method means nothing) is shaded as at that bound, so the result stays
// finite and continuous.
const float MB_AREA_LIGHT_MAX_SIN_ALPHA = 0.95;

// A sphere of `radius` centred at `toCenter`, as the surface sees it: the geometry of its
// centre direction, sin of its angular radius, the horizon-wrapped cosine and the illuminance.
// `intensity` is the luminous intensity of the whole sphere, so that above the horizon
// E = I * falloff(d): a Lambertian sphere of luminance L has I = pi R^2 L and gives
// E = pi L sin^2(alpha) = I / d^2 (Karis 2013, "Sphere Lights": the sphere's irradiance is the
// point light's). Inside the light the falloff is taken at the radius (the sphere's surface).
struct MbSphereView {
    Geometry g;
    float sinAlpha;
    float cosine;
    vec3 illuminance;
};

MbSphereView mb_sphere_view(ShadingFrame f, vec3 toCenter, float radius, vec3 intensity, float falloffRadius) {
    MbSphereView s;
    float d = length(toCenter);
    // At the centre itself there is no direction: take the normal (any choice is finite).
    vec3 l = d > 0.0 ? toCenter / d : f.n;
    float dLight = max(d, radius);
    s.g = makeGeometry(f.n, f.v, l);
    s.sinAlpha = dLight > 0.0 ? min(radius / dLight, MB_AREA_LIGHT_MAX_SIN_ALPHA) : 0.0;
    // Seed 002, implementation notes 1-2 (UE4): n.l from the centre, wrapped where the sphere crosses the
    // horizon; UE4 multiplies diffuse and specular alike by it.
    s.cosine = MB_SLOT_sphere_horizon_wrap(s.g, s.sinAlpha);
    s.illuminance = intensity * MB_SLOT_light_falloff(l * dLight, falloffRadius);
    return s;
}

// GGX D has the factor chi+(n.h) (Walter et al. 2007, eq. 33): no microfacet faces away from
// n. A representative direction may lie so far below the horizon (the light itself still
// partly above it) that its half vector does; its D is then 0, whatever the bound D brick
// (declared for n.h >= 0) would return for the clamped geometry. n.h <= 1e-4 counts as facing
// away: inside a tube's ball and behind the mirror ray the representative direction is
// exactly -r, whose half vector lies in the tangent plane (n.h = 0 up to rounding), and fp32
// and double would otherwise take different sides of the jump from alpha^2 / pi to 0.
const float MB_AREA_LIGHT_MIN_NOH = 1e-4;

bool mb_facing(Geometry gD) {
    return gD.NoH > MB_AREA_LIGHT_MIN_NOH;
}
#endif

#ifdef MB_LIGHT_SPHERE
// Seed 002 "Sphere Lights": D at Karis's representative point (the point of the sphere closest
// to the mirror ray) times the energy normalization; diffuse, V and F at the centre direction;
// both lobes times the horizon-wrapped cosine. The representative direction comes from the
// sphere_light_point role (a tube_light_point brick, called with a zero-length segment: the
// tube bricks' sphere step is Karis's sphere closest point, eqs. 11-12), built from vectors.
// An earlier form took D at the n.h of the sphere_max_noh bricks and rebuilt a direction from
// it; one fp32 n.h carries an angle error ~6e-7 / sin(theta_h), which GGX D amplifies by up to
// 2 / alpha (13% at roughness 0.04, docs/models/lights.md), so the direction is passed instead.
vec3 mb_shade_sphere_representative(ShadingPixel px, ShadingFrame f, SphereLight light) {
    MbSphereView s = mb_sphere_view(f, light.toCenter, light.radius, light.intensity, light.falloffRadius);
    vec3 lD = MB_SLOT_sphere_light_point(s.g, light.toCenter, light.toCenter, light.radius);
    // The shading point on the sphere's centre has no direction (the brick's normalize(0)):
    // the centre direction stands in (false for NaN too).
    lD = dot(lD, lD) > 0.5 ? lD : s.g.l;
    Geometry gD = makeGeometry(f.n, f.v, lD);
    float energy = mb_facing(gD) ? MB_SLOT_sphere_energy_normalization(s.g, px.alpha, s.sinAlpha) : 0.0;
    return MB_SATURATE_MEDIUMP(mb_standard_light(px, f, s.g, gD, energy, s.cosine, s.cosine) * s.illuminance);
}
#endif

#ifdef MB_LIGHT_TUBE
// Karis 2013 ("Tube Lights"; UE4 LineIrradiance) approximates the irradiance of a segment
// L0..L1 whose elements emit I / length each as
//   E / I = (n.L0/|L0| + n.L1/|L1|) / (|L0||L1| + L0.L1).
// With u0, u1 the unit endpoint directions, theta their angle and w = (u0 + u1) / |u0 + u1|:
// n.u0 + n.u1 = 2 cos(theta/2) n.w and |L0||L1| + L0.L1 = 2 |L0||L1| cos^2(theta/2), so
//   E / I = n.w / (|L0||L1| cos(theta/2)):
// a point light in the bisector direction w at distance sqrt(|L0||L1| cos(theta/2)). This
// returns that point; the tube is shaded as a sphere of its radius there (the falloff brick's
// window and bias applied at that distance, the horizon wrap for the radius). Zero length gives
// the centre, so a zero-length tube is the sphere light.
vec3 mb_tube_equivalent_point(ShadingFrame f, vec3 L0, vec3 L1) {
    float d0 = length(L0);
    float d1 = length(L1);
    vec3 u0 = d0 > 0.0 ? L0 / d0 : vec3(0.0);
    vec3 u1 = d1 > 0.0 ? L1 / d1 : vec3(0.0);
    vec3 bisector = u0 + u1;  // length 2 cos(theta/2): no cancellation in 1 + cos(theta)
    float b = length(bisector);
    vec3 w = b > 0.0 ? bisector / b : f.n;  // the segment through the shading point: any w
    return w * sqrt(d0 * d1 * (0.5 * b));
}

// Seed 002 "Tube Lights": D at the tube_light_point brick's representative direction times
// the tube's energy normalization; diffuse, V, F and the cosine from the equivalent sphere.
vec3 mb_shade_tube_representative(ShadingPixel px, ShadingFrame f, TubeLight light) {
    vec3 P = mb_tube_equivalent_point(f, light.toStart, light.toEnd);
    MbSphereView s = mb_sphere_view(f, P, light.radius, light.intensity, light.falloffRadius);
    vec3 lD = MB_SLOT_tube_light_point(s.g, light.toStart, light.toEnd, light.radius);
    // A segment through the shading point has its representative point there, and the brick's
    // normalize(0) is NaN: fall back to the equivalent direction. (The comparison is false for
    // NaN, which is what selects the fallback.)
    lD = dot(lD, lD) > 0.5 ? lD : s.g.l;
    Geometry gD = makeGeometry(f.n, f.v, lD);
    float energy =
        mb_facing(gD) ? MB_SLOT_tube_energy_normalization(gD, px.alpha, light.toStart, light.toEnd, light.radius) : 0.0;
    return MB_SATURATE_MEDIUMP(mb_standard_light(px, f, s.g, gD, energy, s.cosine, s.cosine) * s.illuminance);
}
#endif

#ifdef MB_LTC_TABLE
// Rectangle and disk lights, and sphere and tube lights by the "ltc" method, by linearly
// transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016;
// docs/models/lights.md "Rectangle and disk lights"). A one-sided Lambertian emitter of
// luminance L sends the radiance L Int f (n.l)+ dw over its solid angle. The specular lobe's
// integral Int D V (n.l) dw (F = 1) is the bound rect_light_ltc_cv / disk_light_ltc_cv brick's:
// norm Int D_M dw with the LTC table's entry at (n.v, roughness), plus the residual's quadrature
// (the plain LTC is 15 % off at the median). Schlick's Fresnel splits as the DFG LUT splits it,
// over the table's magnitudes: f0 + (1 - f0) fresnel / norm (F90 = 1; the table's lobe is GGX
// with the height-correlated Smith V, so the D, V and Fresnel roles are not called for these
// lights). The diffuse brick is taken at the light centre's direction times the exact irradiance
// per unit luminance, pi times the light's form factor (the polygon brick with M = I): exact for
// Lambert. The sheen is its own lobe's integral, by the sheen table (shaderlib/ltc/charlie.json,
// Charlie D and Ashikhmin V: the sheen roles are not called for these lights either) and the
// *_light_ltc_sheen bricks, times sheenColor, over the base scaled as for every light; the clear
// coat is a second lobe about the coat's normal at the coat's roughness, attenuating the layers
// below by 1 - strength Fc(nc.v), as the coat's image-based light does.
// `specular` is the base's lobe integral, `magnitude` its table entry's (norm, fresnel),
// `formFactor` Int (n.l)+ dw / pi, `coat` the coat's lobe integral (0 without a clear coat),
// `sheen` the sheen lobe's (0 without a sheen).
vec3 mb_standard_ltc_light(ShadingPixel px, ShadingFrame f, Geometry g, vec2 magnitude, float specular,
                           float formFactor, float coat, vec2 coatMagnitude, float sheen, vec3 luminance) {
    vec3 Fr = ((px.f0 * (magnitude.x - magnitude.y) + magnitude.y) * (specular / magnitude.x)) * px.energyCompensation;
    float irradiance = MB_PI * formFactor;
    vec3 Fd = px.diffuseColor * (MB_SLOT_diffuse(g, px.perceptualRoughness, px.alpha) * irradiance);
    vec3 color = Fd + Fr;
#ifdef MB_FEATURE_SHEEN
    color = color * px.sheen.scaling + px.sheen.color * sheen;
#endif
#ifdef MB_FEATURE_CLEARCOAT
    float coatAttenuation;
    vec3 coatLobe = mb_clearcoat_ltc(px.clearCoat, f, coat, coatMagnitude, coatAttenuation);
    color = color * coatAttenuation + coatLobe;
#endif
    return MB_SATURATE_MEDIUMP(color * luminance);
}

// The table's lobe is GGX at alpha = r^2 (shaderlib/ltc/ggx.json), fitted and validated from
// r = MB_LTC_MIN_ROUGHNESS: these lights shade a smoother surface (or coat) at that roughness,
// just above Filament's own floor of 0.045; the roughness role is not used for them.
const float MB_LTC_MIN_ROUGHNESS = 0.05;
// The LTC bricks' domain starts at n.v = 0.001 (their slots' geometry): a view nearer the
// horizon than that, or below it (a coat normal tilted away from it, an interpolated normal), is
// lifted to it about n for the lobes. Only silhouettes are affected; there the table's M is
// nearly singular and the residual's fp32 quadrature loses its accuracy.
const float MB_LTC_MIN_N_DOT_V = 0.001;
vec3 mb_ltc_view(vec3 n, vec3 v) {
    float NoV = dot(n, v);
    if (NoV >= MB_LTC_MIN_N_DOT_V) return v;
    vec3 t = v - n * NoV;
    float len = length(t);
    // v = -n has no direction along the surface: any will do.
    vec3 along = len > 1e-6 ? t / len : normalize(cross(n, abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0)));
    return along * sqrt(1.0 - MB_LTC_MIN_N_DOT_V * MB_LTC_MIN_N_DOT_V) + n * MB_LTC_MIN_N_DOT_V;
}

// The shapes mb_ltc_area_light integrates.
const int MB_LTC_RECT = 0;
const int MB_LTC_DISK = 1;
const int MB_LTC_SPHERE = 2;
const int MB_LTC_TUBE = 3;

// The integrals mb_standard_ltc_light takes, for one light: the form factor by the shape's
// polygon brick with M = I, then the base's and the coat's lobes by its control-variate brick and
// the sheen's by its sheen brick, one call site each in a loop (each inlined copy of the integration costs lavapipe's JIT time,
// common/ltc.glsl). `toCenter` gives the direction of the diffuse brick's light (a tube's
// equivalent point); a rectangle or disk is (toCenter, a = halfX, b = halfY), a sphere
// (toCenter, radius), a tube (a = L0, b = L1, radius).
vec3 mb_ltc_area_light(ShadingPixel px, ShadingFrame f, int shape, vec3 toCenter, vec3 a, vec3 b, float radius,
                       vec3 luminance) {
    float d = length(toCenter);
    // The centre's direction; the normal where the shading point is the centre, which has none.
    Geometry g = makeGeometry(f.n, f.v, d > 0.0 ? toCenter / d : f.n);
    Geometry gb = makeGeometry(f.n, mb_ltc_view(g.n, g.v), g.l);
    float r = clamp(px.perceptualRoughness, MB_LTC_MIN_ROUGHNESS, 1.0);
    vec4 m = mb_fetch_ltc_matrix(gb.NoV, r);
    vec2 magnitude = mb_fetch_ltc_magnitude(gb.NoV, r);
    // The lobes integrated: 0 the base's specular, 1 the coat's, 2 the sheen's; the ones the
    // material lacks are skipped (constants the compiler folds).
#ifdef MB_FEATURE_CLEARCOAT
    vec3 nc = normalize(px.clearCoat.normal);
    Geometry gc = makeGeometry(nc, mb_ltc_view(nc, g.v), g.l);
    float rC = clamp(px.clearCoat.perceptualRoughness, MB_LTC_MIN_ROUGHNESS, 1.0);
    vec4 mc = mb_fetch_ltc_matrix(gc.NoV, rC);
    vec2 magnitudeC = mb_fetch_ltc_magnitude(gc.NoV, rC);
    const bool hasCoat = true;
#else
    Geometry gc = gb;
    vec4 mc = m;
    vec2 magnitudeC = magnitude;
    float rC = r;
    const bool hasCoat = false;
#endif
#ifdef MB_FEATURE_SHEEN
    // The sheen's table is fitted from the same roughness floor; its lobe is about n with the
    // base's (lifted) view.
    float rS = clamp(px.sheen.perceptualRoughness, MB_LTC_MIN_ROUGHNESS, 1.0);
    vec4 ms = mb_fetch_ltc_sheen_matrix(gb.NoV, rS);
    float normS = mb_fetch_ltc_sheen_magnitude(gb.NoV, rS).x;
    const bool hasSheen = true;
#else
    vec4 ms = m;
    float normS = magnitude.x;
    float rS = r;
    const bool hasSheen = false;
#endif
    float formFactor = 0.0;
#ifdef MB_LIGHT_RECT
    if (shape == MB_LTC_RECT) formFactor = MB_SLOT_rect_light_ltc(g, 1.0, 0.0, 0.0, 1.0, toCenter, a, b);
#endif
#ifdef MB_LIGHT_DISK
    if (shape == MB_LTC_DISK) formFactor = MB_SLOT_disk_light_ltc(g, 1.0, 0.0, 0.0, 1.0, toCenter, a, b);
#endif
#ifdef MB_LIGHT_SPHERE_LTC
    if (shape == MB_LTC_SPHERE) formFactor = MB_SLOT_sphere_light_ltc(g, 1.0, 0.0, 0.0, 1.0, toCenter, radius);
#endif
#ifdef MB_LIGHT_TUBE_LTC
    if (shape == MB_LTC_TUBE) formFactor = MB_SLOT_tube_light_ltc(g, 1.0, 0.0, 0.0, 1.0, a, b, radius);
#endif
    float lobe[3] = float[3](0.0, 0.0, 0.0);
    for (int k = 0; k < 3; ++k) {
        if ((k == 1 && !hasCoat) || (k == 2 && !hasSheen)) continue;
        Geometry gk = k == 1 ? gc : gb;
        vec4 mk = k == 1 ? mc : (k == 2 ? ms : m);
        float rK = k == 1 ? rC : (k == 2 ? rS : r);
        float alphaK = rK * rK;
        float normK = k == 1 ? magnitudeC.x : (k == 2 ? normS : magnitude.x);
        float value = 0.0;
        if (k == 2) {
#if defined(MB_FEATURE_SHEEN) && defined(MB_LIGHT_RECT)
            if (shape == MB_LTC_RECT)
                value = MB_SLOT_rect_light_ltc_sheen(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, a, b);
#endif
#if defined(MB_FEATURE_SHEEN) && defined(MB_LIGHT_DISK)
            if (shape == MB_LTC_DISK)
                value = MB_SLOT_disk_light_ltc_sheen(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, a, b);
#endif
#if defined(MB_FEATURE_SHEEN) && defined(MB_LIGHT_SPHERE_LTC)
            if (shape == MB_LTC_SPHERE)
                value = MB_SLOT_sphere_light_ltc_sheen(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, radius);
#endif
#if defined(MB_FEATURE_SHEEN) && defined(MB_LIGHT_TUBE_LTC)
            if (shape == MB_LTC_TUBE)
                value = MB_SLOT_tube_light_ltc_sheen(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, a, b, radius);
#endif
        } else {
#ifdef MB_LIGHT_RECT
            if (shape == MB_LTC_RECT)
                value = MB_SLOT_rect_light_ltc_cv(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, a, b);
#endif
#ifdef MB_LIGHT_DISK
            if (shape == MB_LTC_DISK)
                value = MB_SLOT_disk_light_ltc_cv(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, a, b);
#endif
#ifdef MB_LIGHT_SPHERE_LTC
            if (shape == MB_LTC_SPHERE)
                value = MB_SLOT_sphere_light_ltc_cv(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, toCenter, radius);
#endif
#ifdef MB_LIGHT_TUBE_LTC
            if (shape == MB_LTC_TUBE)
                value = MB_SLOT_tube_light_ltc_cv(gk, alphaK, normK, mk.x, mk.y, mk.z, mk.w, a, b, radius);
#endif
        }
        lobe[k] = value;
    }
    return mb_standard_ltc_light(px, f, g, magnitude, lobe[0], formFactor, lobe[1], magnitudeC, lobe[2], luminance);
}
#endif

#if defined(MB_LIGHT_SPHERE_LTC) || defined(MB_LIGHT_TUBE_LTC)
// Sphere and tube lights by the "ltc" method (docs/models/lights.md "Sphere and tube lights by
// LTC"). They are given by intensity: a Lambertian sphere of radius R and luminance L has
// I = pi R^2 L, and a capsule of radius R and length len is given the intensity it has seen
// broadside, I = (pi R^2 + 2 R len) L. The light_falloff brick's window and bias apply as they do
// to the representative point: the luminance is I falloff(d) d^2 / A, so that a small light
// above the horizon has the irradiance I falloff(d), whichever the method. A light whose
// equivalent angular radius sqrt(A / pi) / d is below MB_LTC_BLEND_START is shaded by the
// representative point, above twice that by LTC, linearly mixed between: on a small light the
// LTC integrals' fp32 error, a few ulps of the polygon's edge sum whatever its size, is divided
// by the light's solid angle (validation's tolerance scales the bricks' by 1 / (pi 0.05^2),
// the role's "toleranceScale"). The handover's cost in accuracy: docs/models/lights.md.
const float MB_LTC_BLEND_START = 0.05;
float mb_ltc_blend(float equivalentSinAlpha) {
    return clamp(equivalentSinAlpha / MB_LTC_BLEND_START - 1.0, 0.0, 1.0);
}
#endif

#ifdef MB_LIGHT_RECT
vec3 mb_shade_rect(ShadingPixel px, ShadingFrame f, RectLight light) {
    return mb_ltc_area_light(px, f, MB_LTC_RECT, light.toCenter, light.halfX, light.halfY, 0.0, light.luminance);
}
#endif

#ifdef MB_LIGHT_DISK
vec3 mb_shade_disk(ShadingPixel px, ShadingFrame f, DiskLight light) {
    return mb_ltc_area_light(px, f, MB_LTC_DISK, light.toCenter, light.halfX, light.halfY, 0.0, light.luminance);
}
#endif

#ifdef MB_LIGHT_SPHERE
vec3 mb_shade_sphere(ShadingPixel px, ShadingFrame f, SphereLight light) {
#ifdef MB_LIGHT_SPHERE_LTC
    // As the representative point, nearer than radius / 0.95 the light is shaded as at that
    // bound (the sphere bricks clamp sin alpha there too).
    float d = length(light.toCenter);
    float dLight = max(d, light.radius / MB_AREA_LIGHT_MAX_SIN_ALPHA);
    float w = dLight > 0.0 ? mb_ltc_blend(light.radius / dLight) : 0.0;
    vec3 color = vec3(0.0);
    if (w < 1.0) color = mb_shade_sphere_representative(px, f, light) * (1.0 - w);
    if (w > 0.0) {
        vec3 l = d > 0.0 ? light.toCenter / d : f.n;
        float area = MB_PI * light.radius * light.radius;
        vec3 luminance = light.intensity * (MB_SLOT_light_falloff(l * dLight, light.falloffRadius) * (dLight * dLight / area));
        color += mb_ltc_area_light(px, f, MB_LTC_SPHERE, light.toCenter, vec3(0.0), vec3(0.0), light.radius, luminance) * w;
    }
    return color;
#else
    return mb_shade_sphere_representative(px, f, light);
#endif
}
#endif

#ifdef MB_LIGHT_TUBE
vec3 mb_shade_tube(ShadingPixel px, ShadingFrame f, TubeLight light) {
#ifdef MB_LIGHT_TUBE_LTC
    // The capsule's area seen broadside and its distance: the equivalent point's, at least
    // sqrt(A / pi) / 0.95 (as the sphere's). The capsule must also stay clear of the shading
    // point: within two radii of the segment (inside the light, or a segment through the point)
    // the representative point takes over, fully at one radius.
    vec3 P = mb_tube_equivalent_point(f, light.toStart, light.toEnd);
    float dEq = length(P);
    vec3 axis = light.toEnd - light.toStart;
    float len = length(axis);
    float area = MB_PI * light.radius * light.radius + 2.0 * light.radius * len;
    float size = sqrt(area / MB_PI);
    float dLight = max(dEq, size / MB_AREA_LIGHT_MAX_SIN_ALPHA);
    float t = len > 0.0 ? clamp(-dot(light.toStart, axis) / (len * len), 0.0, 1.0) : 0.0;
    float h = length(light.toStart + axis * t);
    float clear = light.radius > 0.0 ? clamp(h / light.radius - 1.0, 0.0, 1.0) : 0.0;
    float w = dLight > 0.0 ? mb_ltc_blend(size / dLight) * clear : 0.0;
    vec3 color = vec3(0.0);
    if (w < 1.0) color = mb_shade_tube_representative(px, f, light) * (1.0 - w);
    if (w > 0.0) {
        vec3 l = dEq > 0.0 ? P / dEq : f.n;
        vec3 luminance = light.intensity * (MB_SLOT_light_falloff(l * dLight, light.falloffRadius) * (dLight * dLight / area));
        color += mb_ltc_area_light(px, f, MB_LTC_TUBE, P, light.toStart, light.toEnd, light.radius, luminance) * w;
    }
    return color;
#else
    return mb_shade_tube_representative(px, f, light);
#endif
}
#endif
