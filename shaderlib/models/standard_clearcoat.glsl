// Standard model, clear coat feature (seed 000 "More PBR / Clear Coating Material", after
// Filament "Physically Based Rendering in Filament" sec. 4.9): a colourless dielectric layer
// (IOR 1.5, F0 = 0.04) over the base, shaded about its own normal: the clearCoatNormal input
// (Filament's clearCoatNormal, glTF clearcoatNormalTexture), a tangent-space normal about the
// geometric normal f.ng, which is the coat's normal by default (seed 000: the coat ignores the
// base's normal map). Its own roughness goes through the `roughness` role.
// Included before the skeleton; the skeleton calls these hooks under MB_FEATURE_CLEARCOAT,
// standard_environment.glsl calls mb_clearcoat_environment under MB_ENV_IBL.

struct ClearCoatPixel {
    float strength;             // clearCoat in [0, 1]
    float perceptualRoughness;  // of the coat
    float alpha;                // MB_SLOT_roughness(perceptualRoughness)
    float ambientOcclusion;     // the material's, for the coat's specular occlusion
    vec3 normal;                // the coat's unit normal, world space
};

// The coat's Fresnel reflectance at normal incidence: IOR 1.5 (seed 000, Filament).
#define MB_CLEARCOAT_F0 0.04

// clearCoatNormal ts in world space, as a normal map is applied (Filament's
// shading_tangentToWorld * clearCoatNormal; glTF 2.0 normalTextureInfo): x along the tangent
// orthonormalized against ng (common/aniso.glsl, which also handles a tangent parallel to ng),
// y along ng x t (glTF's bitangent for tangent.w = +1), z along ng. (0, 0, z > 0) is ng
// exactly, so the default changes nothing; a vector of (nearly) zero length has no direction
// and keeps ng.
vec3 mb_clearcoat_normal(vec3 ts, ShadingFrame f) {
    if (ts.x == 0.0 && ts.y == 0.0 && ts.z > 0.0) return f.ng;
    vec3 t = mb_aniso_tangent(f.ng, f.t);
    vec3 nc = t * ts.x + cross(f.ng, t) * ts.y + f.ng * ts.z;
    float len2 = dot(nc, nc);
    return len2 > 1e-12 ? nc * inversesqrt(len2) : f.ng;
}

ClearCoatPixel mb_clearcoat_prepare(MaterialInputs m, ShadingFrame f, inout vec3 f0, inout float perceptualRoughness) {
    ClearCoatPixel cc;
    cc.strength = m.clearCoat;
    cc.perceptualRoughness = m.clearCoatRoughness;
    cc.alpha = MB_SLOT_roughness(cc.perceptualRoughness);
    cc.ambientOcclusion = m.ambientOcclusion;
    cc.normal = mb_clearcoat_normal(m.clearCoatNormal, f);
    // Under the coat the base's outer medium is IOR 1.5, not air: F0ClearCoatToSurface (seed
    // 000; the f0_clearcoat role), blended by the coat's strength as Filament does, so that
    // clearCoat = 0 leaves f0 exactly unchanged (mix(a, b, 0) = a). glTF binds
    // f0_clearcoat_none: KHR_materials_clearcoat leaves the base as it is.
    f0 = mix(f0, MB_SLOT_f0_clearcoat(f0), cc.strength);
    // The clearcoat_base_roughness role: seed 000 raises the base to the coat's roughness by
    // clearCoat (coat_base_roughness_max); glTF keeps it (coat_base_roughness_keep).
    perceptualRoughness = MB_SLOT_clearcoat_base_roughness(perceptualRoughness, cc.perceptualRoughness, cc.strength);
    return cc;
}

// The coat's specular for light direction l, about the coat's normal nc, times its own
// saturate(nc.l) (the base's share already carries n.l): strength * D * V * Fc * (nc.l).
// attenuation = 1 - strength * Fc is what reaches the base and comes back (Filament's
// clearCoatLobe; Fc at l.h, as Filament).
vec3 mb_clearcoat_direct(ClearCoatPixel cc, ShadingFrame f, vec3 l, out float attenuation) {
    Geometry g = makeGeometry(cc.normal, f.v, l);
    float D = MB_SLOT_clearcoat_d(g, cc.alpha);
    float V = MB_SLOT_clearcoat_v(g, cc.alpha);
    float Fc = MB_SLOT_clearcoat_fresnel(g, vec3(MB_CLEARCOAT_F0), 1.0).x * cc.strength;
    attenuation = 1.0 - Fc;
    // Cosine on V before D, as the core does: at fp16 D * V alone may overflow where n.l = 0.
    // chi+(nc.h) (Walter et al. 2007, eq. 33): no coat microfacet faces h when h is below the
    // coat's plane, which happens here, unlike for the base, with nc.l > 0: the viewer is below
    // nc's horizon (nc.v < -nc.l; nc is not the shading normal). makeGeometry clamps nc.h to 0
    // there, and a D brick evaluated at n.h = 0 gives its grazing value (alpha^2 / pi for GGX).
    float lobe = g.NoH > 0.0 ? D * (V * g.NoL) : 0.0;
#ifdef MB_FP16
    lobe = min(lobe, 65504.0);  // Filament's saturateMediump, as in the core
#endif
    return vec3(lobe * Fc);
}

#ifdef MB_LTC_TABLE
// The coat under a light shaded by linearly transformed cosines, per unit luminance (standard_lights.glsl): its lobe's
// integral `coatIntegral` (about its normal, at its roughness; the table's entry there gives
// `magnitude` = (norm, fresnel)) times Schlick's Fresnel split over the table (F0 = 0.04,
// F90 = 1) and the strength; attenuation = 1 - strength Fc(nc.v), as for image-based light.
vec3 mb_clearcoat_ltc(ClearCoatPixel cc, ShadingFrame f, float coatIntegral, vec2 magnitude, out float attenuation) {
    Geometry g = makeGeometry(cc.normal, f.v, reflect(-f.v, cc.normal));
    attenuation = 1.0 - MB_SLOT_clearcoat_fresnel(g, vec3(MB_CLEARCOAT_F0), 1.0).x * cc.strength;
    float fresnel = (MB_CLEARCOAT_F0 * (magnitude.x - magnitude.y) + magnitude.y) / magnitude.x;
    return vec3(fresnel * coatIntegral * cc.strength);
}
#endif

#ifdef MB_ENV_IBL
// The coat's image-based specular (Filament evaluateClearCoatIBL): the prefiltered radiance
// along r = reflect(-v, nc) at the coat's mip level, times Fc(nc.v) * strength and the
// specular occlusion of the coat (the specular_occlusion role about nc, with nc as its
// horizon normal, the material ao times env.ao and the coat's roughness).
// attenuation = 1 - Fc(nc.v) * strength. Geometry with l = r: its v.h is |v + r| / 2 =
// |nc.v|, so the Fresnel brick sees v.h = n.v.
vec3 mb_clearcoat_environment(ClearCoatPixel cc, ShadingFrame f, Environment env, out float attenuation) {
    vec3 r = reflect(-f.v, cc.normal);
    Geometry g = makeGeometry(cc.normal, f.v, r);
    float Fc = MB_SLOT_clearcoat_fresnel(g, vec3(MB_CLEARCOAT_F0), 1.0).x * cc.strength;
    attenuation = 1.0 - Fc;
    float lod = MB_SLOT_mip_mapping(cc.perceptualRoughness, g.NoV, env.maxMip);
    float occlusion = MB_SLOT_specular_occlusion(g, cc.normal, env.ao * cc.ambientOcclusion, cc.perceptualRoughness);
    return mb_fetch_prefiltered(r, lod) * (Fc * occlusion);
}
#endif
