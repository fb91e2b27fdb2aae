// Standard shading model skeleton: diffuse + Cook-Torrance specular (seed 000 "BRDF
// Assembly", seed 002 "Shading Model"), with the optional layers of seed 000 "More PBR" as
// features. The emitter binds each MB_SLOT_<role> macro to the brick the material picked,
// so the skeleton never names a brick (contract: docs/models.md).
// F0 = mix(f0Dielectric, baseColor, metallic) and diffuseColor = baseColor * (1 - metallic)
// (seed 003, with f0Dielectric = 0.04 by default).
//
// Files: this one (pixel preparation, the BRDF of one light direction, directional light),
// standard_lights.glsl (point, spot, sphere, tube), standard_environment.glsl (SH9 and
// prefiltered image-based light), and the feature fragments standard_<feature>.glsl, which
// are included before this file and define the hooks called under MB_FEATURE_<NAME>.

struct ShadingPixel {
    vec3 diffuseColor;
    float perceptualRoughness;  // after the clear coat clamp
    float alpha;                // MB_SLOT_roughness(perceptualRoughness)
    vec3 f0;                    // after the clear coat's F0 conversion
    float NoV;                  // clamped to MB_MIN_N_DOT_V, as in makeGeometry
    // DFG terms of the environment BRDF (x = Int Gv Fc, y = Int Gv, z = cloth), from the LUT
    // (ibl_lut) or the analytic env BRDF (ibl_analytic: x, y only); (0, 1, 0) otherwise.
    vec3 dfg;
    vec3 energyCompensation;    // multiscatter factor on the specular lobes; 1 without IBL
    vec3 emissive;
    float ambientOcclusion;
#ifdef MB_FEATURE_CLEARCOAT
    ClearCoatPixel clearCoat;
#endif
#ifdef MB_FEATURE_ANISOTROPY
    AnisotropyPixel anisotropy;
#endif
#ifdef MB_FEATURE_SHEEN
    SheenPixel sheen;
#endif
};

#ifdef MB_ENV_IBL
// standard_environment.glsl: the DFG terms and the multiscatter factor.
void mb_environment_prepare(inout ShadingPixel px, ShadingFrame f);
#endif

ShadingPixel mb_prepare(MaterialInputs m, ShadingFrame f) {
    ShadingPixel px;
    px.perceptualRoughness = m.roughness;
    px.f0 = mix(m.f0Dielectric, m.baseColor, m.metallic);
    px.diffuseColor = m.baseColor * (1.0 - m.metallic);
    px.NoV = max(dot(f.n, f.v), MB_MIN_N_DOT_V);
    px.emissive = m.emissive;
    px.ambientOcclusion = m.ambientOcclusion;
#ifdef MB_FEATURE_CLEARCOAT
    px.clearCoat = mb_clearcoat_prepare(m, f, px.f0, px.perceptualRoughness);
#endif
    px.alpha = MB_SLOT_roughness(px.perceptualRoughness);
#ifdef MB_FEATURE_ANISOTROPY
    px.anisotropy = mb_anisotropy_prepare(m, f, px.alpha);
#endif
    px.dfg = vec3(0.0, 1.0, 0.0);
    px.energyCompensation = vec3(1.0);
#ifdef MB_ENV_IBL
    mb_environment_prepare(px, f);
#endif
#ifdef MB_FEATURE_SHEEN
    px.sheen = mb_sheen_prepare(m, f, px.NoV);
#endif
    return px;
}

// Radiance per unit illuminance of one light direction. `g` is the geometry of the light's
// (centre) direction: diffuse, V and F use it. `gD` is the geometry at which D is evaluated
// (the representative direction of an area light; g for punctual lights) and `dScale` the
// energy normalization on D (1 for punctual lights). `diffuseCos` and `specularCos` are the
// cosine factors (saturate(n.l), or an area light's horizon-wrapped form).
vec3 mb_standard_light(ShadingPixel px, ShadingFrame f, Geometry g, Geometry gD, float dScale,
                       float diffuseCos, float specularCos) {
#ifdef MB_FEATURE_ANISOTROPY
    float D, V;
    mb_anisotropy_dv(px.anisotropy, f, g, gD, D, V);
#else
    float D = MB_SLOT_specular_d(gD, px.alpha);
    float V = MB_SLOT_specular_v(g, px.alpha);
#endif
    vec3 F = MB_SLOT_fresnel(g, px.f0, 1.0);
    // The cosine multiplies V before D: at fp16, D and V near a grazing, sharp peak each fit
    // in half but D * V does not, and (D * V) * n.l would give Inf * 0 = NaN where n.l = 0.
    float specular = (D * dScale) * (V * specularCos);
#ifdef MB_FP16
    // Filament's saturateMediump: the per-unit-illuminance specular is clamped to the largest
    // half (65504) so that a dim light (illuminance < 1) times a peak too bright for half at
    // unit illuminance stays finite; Inf remains only where the exact radiance overflows half.
    specular = min(specular, 65504.0);
#endif
    vec3 Fr = (specular * F) * px.energyCompensation;
    vec3 Fd = px.diffuseColor * (MB_SLOT_diffuse(g, px.perceptualRoughness, px.alpha) * diffuseCos);
    vec3 color = Fd + Fr;
#ifdef MB_FEATURE_SHEEN
    color = color * px.sheen.scaling + mb_sheen_direct(px.sheen, g, gD, specularCos);
#endif
#ifdef MB_FEATURE_CLEARCOAT
    float coatAttenuation;
    vec3 coat = mb_clearcoat_direct(px.clearCoat, f, g.l, coatAttenuation);
    color = color * coatAttenuation + coat;
#endif
    return color;
}

#ifdef MB_LIGHT_DIR
vec3 mb_shade_dir(ShadingPixel px, ShadingFrame f, DirectionalLight light) {
    Geometry g = makeGeometry(f.n, f.v, light.l);
    return MB_SATURATE_MEDIUMP(mb_standard_light(px, f, g, g, 1.0, g.NoL, g.NoL) * light.illuminance);
}
#endif

vec3 mb_emission(ShadingPixel px) {
    return px.emissive;
}
