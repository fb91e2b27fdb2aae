// Standard model, anisotropy feature (seed 000 "More PBR / Anisotropic Specular Material";
// Filament "Physically Based Rendering in Filament" sec. 4.10): the base's D and V become
// the anisotropic bricks with the roughness stretched along the tangent f.t (anisotropy > 0)
// or the bitangent n x t (< 0); image-based light uses the Far Cry 4 bent normal.
// Included before the skeleton; the skeleton calls these hooks under MB_FEATURE_ANISOTROPY,
// standard_environment.glsl calls mb_anisotropy_ibl_normal under MB_ENV_IBL.

struct AnisotropyPixel {
    float anisotropy;  // in [-1, 1]
    float at;          // alpha along t
    float ab;          // alpha along b = n x t
};

// Filament's MIN_ROUGHNESS (MIN_PERCEPTUAL_ROUGHNESS^2): 0.045^2 in fp32, 0.089^2 in fp16 (the
// half floor of roughness_clamped_fp16), so that at and ab stay inside the bricks' domain.
#ifdef MB_FP16
#define MB_ANISOTROPY_MIN_ALPHA 0.007921
#else
#define MB_ANISOTROPY_MIN_ALPHA 0.002025
#endif

// The anisotropy_alpha role maps alpha and the anisotropy to the alphas along t and b:
// Filament's at = alpha (1 + a), ab = alpha (1 - a) by default (Kulla & Conty 2017), glTF's
// at = mix(alpha, 1, a^2), ab = alpha for imported glTF. Each is at least
// MB_ANISOTROPY_MIN_ALPHA; anisotropy = 0 gives at = ab = max(alpha, MIN) with both.
AnisotropyPixel mb_anisotropy_prepare(MaterialInputs m, ShadingFrame f, float alpha) {
    AnisotropyPixel a;
    a.anisotropy = m.anisotropy;
    vec3 alphas = MB_SLOT_anisotropy_alpha(alpha, m.anisotropy);
    a.at = max(alphas.x, MB_ANISOTROPY_MIN_ALPHA);
    a.ab = max(alphas.y, MB_ANISOTROPY_MIN_ALPHA);
    return a;
}

// D at the representative geometry gD (area lights), V at the light's geometry g, both with
// the interpolated tangent (the bricks orthonormalize it against n).
void mb_anisotropy_dv(AnisotropyPixel a, ShadingFrame f, Geometry g, Geometry gD, out float D, out float V) {
    D = MB_SLOT_specular_d_aniso(gD, f.t, a.at, a.ab);
    V = MB_SLOT_specular_v_aniso(g, f.t, a.at, a.ab);
}

#ifdef MB_ENV_IBL
// The normal the base's prefiltered lookup reflects v about (McAuley 2015, "Rendering the
// World of Far Cry 4"; seed 000): the bent_normal_aniso role. The Geometry's l is the mirror
// direction reflect(-v, n); the bricks read only n and v from it.
vec3 mb_anisotropy_ibl_normal(AnisotropyPixel a, ShadingFrame f, float perceptualRoughness) {
    Geometry g = makeGeometry(f.n, f.v, reflect(-f.v, f.n));
    return MB_SLOT_bent_normal_aniso(g, f.t, a.anisotropy, perceptualRoughness);
}
#endif
