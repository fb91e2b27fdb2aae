// Standard model, sheen feature (Filament "Physically Based Rendering in Filament" sec. 4.12.2
// "Sheen"; KHR_materials_sheen; seed 000 "Fabric Material" for the lobe, seed 004): a sheen
// lobe D_sheen * V_sheen * sheenColor over the base (no Fresnel: sheenColor is the
// reflectance, as Filament), the base scaled by the share the sheen leaves,
//   scaling = max(1 - max(sheenColor) * E(n.v, sheenRoughness), 0),
// with E the sheen lobe's directional albedo (Conty & Kulla 2017's albedo scaling).
// Included before the skeleton; the skeleton calls these hooks under MB_FEATURE_SHEEN,
// standard_environment.glsl calls mb_sheen_environment under MB_ENV_IBL.

struct SheenPixel {
    vec3 color;
    float perceptualRoughness;
    float alpha;             // MB_SLOT_roughness(perceptualRoughness): Charlie's r
    float albedo;            // E(n.v, perceptualRoughness)
    float ambientOcclusion;  // the material's, for the sheen's specular occlusion
    float scaling;           // the base layer's share
};

#ifndef MB_ENV_IBL_LUT
// Without a DFG LUT: an empirical fit of the Charlie sheen albedo over (n.v, perceptual
// roughness), from Dassault Systemes' Enterprise PBR reference renderer (also Babylon.js
// getBRDFLookupCharlieSheen):
//   E = 0.65584461 (1 - n.v)^3 + 1 / (4.16526551 + exp(6.33516894 - 7.97291361 r))
// Its error against this library's cloth LUT channel (Charlie D, Ashikhmin V) is measured in
// tests/test_model_features.cpp and stated in docs/models/features.md.
float mb_sheen_albedo_fit(float NoV, float perceptualRoughness) {
    float c = 1.0 - NoV;
    return 0.65584461 * (c * c * c) + 1.0 / (4.16526551 + exp(6.33516894 - 7.97291361 * perceptualRoughness));
}
#endif

SheenPixel mb_sheen_prepare(MaterialInputs m, ShadingFrame f, float NoV) {
    SheenPixel s;
    s.color = m.sheenColor;
    s.perceptualRoughness = m.sheenRoughness;
    s.alpha = MB_SLOT_roughness(s.perceptualRoughness);
    s.ambientOcclusion = m.ambientOcclusion;
#ifdef MB_ENV_IBL_LUT
    // The LUT's cloth channel (DESIGN.md "DFG LUT convention", Filament's sheenDFG).
    s.albedo = mb_fetch_dfg(NoV, s.perceptualRoughness).z;
#else
    s.albedo = mb_sheen_albedo_fit(NoV, s.perceptualRoughness);
#endif
    // Clamped at 0: the cloth channel (Charlie D, Ashikhmin V) exceeds 1 at grazing views and
    // low sheen roughness (1.74 at n.v = 0.05, r = 0.1), where 1 - E would turn the base
    // negative; Filament leaves it unclamped. The fit stays below 0.89, so it never clamps.
    s.scaling = max(1.0 - max(s.color.r, max(s.color.g, s.color.b)) * s.albedo, 0.0);
    return s;
}

// The sheen lobe for one light: D at gD (an area light's representative direction), V at g,
// times sheenColor and the cosine factor (Filament's sheenLobe, times n.l).
vec3 mb_sheen_direct(SheenPixel s, Geometry g, Geometry gD, float cosine) {
    float D = MB_SLOT_sheen_d(gD, s.alpha);
    float V = MB_SLOT_sheen_v(g, s.alpha);
    // Zero where the cosine is 0 or V has a pole: v_charlie's Lambda fit makes V infinite at
    // n.l = 0 (its domain starts at n.l = 1e-3), and inf * 0 would be NaN. The limit there is 0
    // (V n.l ~ 1 / Lambda(n.l) -> 0). An area light whose centre is below the horizon has a
    // wrapped cosine > 0 at n.l = 0; Ashikhmin's finite V still shades it.
    float lobe = (cosine > 0.0 && !isinf(V)) ? D * (V * cosine) : 0.0;
#ifdef MB_FP16
    // Half only: below n.l = 1e-3 (v_charlie's declared domain) the half-precision V is
    // rounding noise (4 n.v n.l underflows; stress measured 65504 per unit illuminance where
    // the exact lobe is 1e-7), so the lobe is dropped there; then Filament's saturateMediump.
    lobe = g.NoL < 0.001 ? 0.0 : min(lobe, 65504.0);
#endif
    return s.color * lobe;
}

#ifdef MB_ENV_IBL
// The sheen's image-based light (Filament evaluateSheenIBL): the prefiltered radiance along
// reflect(-v, n) at the sheen roughness's mip level, times sheenColor, the albedo E (the LUT's
// cloth channel in ibl_lut, the fit in ibl_analytic) and the specular_occlusion role with the
// sheen roughness.
vec3 mb_sheen_environment(SheenPixel s, ShadingFrame f, Environment env) {
    vec3 r = reflect(-f.v, f.n);
    Geometry g = makeGeometry(f.n, f.v, r);
    float lod = MB_SLOT_mip_mapping(s.perceptualRoughness, g.NoV, env.maxMip);
    float occlusion = MB_SLOT_specular_occlusion(g, f.ng, env.ao * s.ambientOcclusion, s.perceptualRoughness);
    return mb_fetch_prefiltered(r, lod) * s.color * (s.albedo * occlusion);
}
#endif
