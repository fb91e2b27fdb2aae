// What an engine passes to a permutation: the shading frame, one struct per light type and
// the environment (docs/models.md). Positions are relative to the shading point
// (toLight = lightPosition - worldPosition); intensities are luminous intensities (colour
// times candela) and become illuminance through the bound light_falloff brick.

struct ShadingFrame {
    vec3 n;   // shading normal (after normal mapping), unit
    vec3 v;   // towards the viewer, unit
    vec3 ng;  // geometric normal: clear coat, horizon specular occlusion
    vec3 t;   // tangent: anisotropy (orthonormalized against n by the bricks)
};

struct DirectionalLight {
    vec3 l;            // unit, towards the light
    vec3 illuminance;  // at the surface, facing the light
};

struct PointLight {
    vec3 toLight;
    vec3 intensity;
    float falloffRadius;  // influence radius (windowed falloff)
};

struct SpotLight {
    vec3 toLight;
    vec3 axis;       // unit, the direction the spot shines in
    vec3 intensity;
    float falloffRadius;
    float cosOuter;  // cosine of the outer half-angle (zero light outside)
    float cosInner;  // cosine of the inner half-angle (full light inside)
};

struct SphereLight {
    vec3 toCenter;
    float radius;
    vec3 intensity;
    float falloffRadius;
};

struct TubeLight {
    vec3 toStart;  // the capsule's segment, from the shading point
    vec3 toEnd;
    float radius;
    vec3 intensity;
    float falloffRadius;
};

// Rectangle and disk lights (docs/models/lights.md, "Rectangle and disk lights"): one-sided
// Lambertian emitters of uniform luminance, shaded by linearly transformed cosines. A rectangle
// has the half-edge vectors halfX and halfY, a disk (an ellipse) the semi-axis vectors; both
// emit on the side cross(halfX, halfY) points to.
struct RectLight {
    vec3 toCenter;
    vec3 halfX;
    vec3 halfY;
    vec3 luminance;  // colour times nits (cd/m^2)
};

struct DiskLight {
    vec3 toCenter;
    vec3 halfX;
    vec3 halfY;
    vec3 luminance;
};

struct Environment {
    vec3 sh[9];    // radiance SH coefficients L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22
    float ao;      // ambient occlusion in [0, 1]
    float maxMip;  // mip level of the roughest prefiltered level
};

// Texture fetches are hooks that the includer defines (the engine, or the validation probe),
// so that validation can feed their values per sample.
vec3 mb_fetch_prefiltered(vec3 r, float lod);
vec3 mb_fetch_dfg(float NoV, float perceptualRoughness);
// The LTC table (shaderlib/ltc/ggx.json) at (n.v, perceptual roughness): M^-1's elements
// (m00, m02, m20, m22) and the lobe's magnitudes (norm, fresnel); the sheen's
// (shaderlib/ltc/charlie.json) at (n.v, sheen roughness): its M^-1 and (norm, 0).
vec4 mb_fetch_ltc_matrix(float NoV, float perceptualRoughness);
vec2 mb_fetch_ltc_magnitude(float NoV, float perceptualRoughness);
vec4 mb_fetch_ltc_sheen_matrix(float NoV, float perceptualRoughness);
vec2 mb_fetch_ltc_sheen_magnitude(float NoV, float perceptualRoughness);

// Filament's smooth spot cone: saturate(cos * scale + offset), squared.
float mb_spot_attenuation(vec3 l, vec3 axis, float cosOuter, float cosInner) {
    float scale = 1.0 / max(cosInner - cosOuter, 1e-4);
    float offset = -cosOuter * scale;
    float a = clamp(dot(-l, axis) * scale + offset, 0.0, 1.0);
    return a * a;
}

// Orthonormal t, b around a unit n, continuous except across n.z = 0's sign flip (Duff et al.
// 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)): a tangent for callers that
// have none, and the validation probe's frame construction.
void mb_orthonormal_basis(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}
