// Cloth shading model skeleton (seed 000 "Fabric Material", seed 004; Filament's cloth
// model, "Physically Based Rendering in Filament" sec. 4.12). Contract: docs/models.md;
// decisions and formulas: docs/models/cloth.md.
//   f_d  = baseColor * MB_SLOT_diffuse, with MB_SLOT_diffuse_wrap in place of saturate(n.l)
//   f_r  = sheenColor * D * V                   (sheenColor is F: no Fresnel, as Filament)
//   L_o  = (f_d * wrap + f_r * saturate(n.l)) * E
// Seed 004 writes the sheen as f * d * v * PI * ndotl: its lights are in radiance units with
// a Lambert diffuse of albedo (no 1/pi); here E is illuminance and the diffuse bricks carry
// 1/pi, so the sheen has no extra pi.

struct ShadingPixel {
    vec3 diffuseColor;
    float perceptualRoughness;
    float alpha;               // MB_SLOT_roughness(perceptualRoughness)
    vec3 sheenColor;
    vec3 subsurfaceColor;
    float wrap;
    float NoV;                 // clamped to MB_MIN_N_DOT_V, as in makeGeometry
    vec3 dfg;                  // DFG LUT texel (ibl_lut; z = cloth channel), else (0, 1, 0)
    vec3 emissive;
    float ambientOcclusion;
};

ShadingPixel mb_prepare(MaterialInputs m, ShadingFrame f) {
    ShadingPixel px;
    px.diffuseColor = m.baseColor;
    px.perceptualRoughness = m.roughness;
    px.alpha = MB_SLOT_roughness(m.roughness);
    px.sheenColor = m.sheenColor;
    px.subsurfaceColor = m.subsurfaceColor;
    px.wrap = m.wrap;
    px.NoV = max(dot(f.n, f.v), MB_MIN_N_DOT_V);
#ifdef MB_ENV_IBL_LUT
    px.dfg = mb_fetch_dfg(px.NoV, px.perceptualRoughness);
#else
    px.dfg = vec3(0.0, 1.0, 0.0);
#endif
    px.emissive = m.emissive;
    px.ambientOcclusion = m.ambientOcclusion;
    return px;
}

// Radiance per unit illuminance from the light direction of g.
vec3 mb_cloth_light(ShadingPixel px, Geometry g) {
    vec3 wrapped = MB_SLOT_diffuse_wrap(g, px.wrap, px.subsurfaceColor);
    vec3 color = px.diffuseColor * (MB_SLOT_diffuse(g, px.perceptualRoughness, px.alpha) * wrapped);
    // The sheen lobe lives on the upper hemisphere. Skipping it below (rather than
    // multiplying by n.l = 0) keeps V's 1/n.l pole (v_charlie) from giving Inf * 0.
    if (g.NoL > 0.0) {
        float D = MB_SLOT_specular_d(g, px.alpha);
        float V = MB_SLOT_specular_v(g, px.alpha);
        color += px.sheenColor * (D * (V * g.NoL));
    }
    return color;
}

#ifdef MB_LIGHT_DIR
vec3 mb_shade_dir(ShadingPixel px, ShadingFrame f, DirectionalLight light) {
    return MB_SATURATE_MEDIUMP(mb_cloth_light(px, makeGeometry(f.n, f.v, light.l)) * light.illuminance);
}
#endif

#ifdef MB_LIGHT_POINT
vec3 mb_shade_point(ShadingPixel px, ShadingFrame f, PointLight light) {
    vec3 illuminance = light.intensity * MB_SLOT_light_falloff(light.toLight, light.falloffRadius);
    return MB_SATURATE_MEDIUMP(mb_cloth_light(px, makeGeometry(f.n, f.v, light.toLight)) * illuminance);
}
#endif

#ifdef MB_LIGHT_SPOT
vec3 mb_shade_spot(ShadingPixel px, ShadingFrame f, SpotLight light) {
    vec3 l = normalize(light.toLight);
    float cone = mb_spot_attenuation(l, light.axis, light.cosOuter, light.cosInner);
    vec3 illuminance = light.intensity * (MB_SLOT_light_falloff(light.toLight, light.falloffRadius) * cone);
    return MB_SATURATE_MEDIUMP(mb_cloth_light(px, makeGeometry(f.n, f.v, l)) * illuminance);
}
#endif

#ifndef MB_ENV_NONE
// SH9 diffuse, weighted by 1 - E in ibl_lut, plus the prefiltered sheen:
//   L = diffuseColor * max(E_irr(n), 0) / pi * ao * max(1 - E, 0) + L_pref(r, lod) * E * occlusion,
//   E = sheenColor * dfg.z, dfg.z = Int D_Charlie V_Ashikhmin (n.l) dw (Filament's cloth
// specularDFG). The wrap and subsurface colour are not applied to the irradiance (docs).
vec3 mb_shade_environment(ShadingPixel px, ShadingFrame f, Environment env) {
    float ao = env.ao * px.ambientOcclusion;
    vec3 diffuse = mb_sh_diffuse(px.diffuseColor, f.n, env, ao);  // common/sh_diffuse.glsl
#ifdef MB_ENV_IBL_LUT
    vec3 E = px.sheenColor * px.dfg.z;
    vec3 r = reflect(-f.v, f.n);
    float lod = MB_SLOT_mip_mapping(px.perceptualRoughness, clamp(dot(f.n, r), MB_MIN_N_DOT_V, 1.0), env.maxMip);
    float occlusion = MB_SLOT_specular_occlusion(makeGeometry(f.n, f.v, r), f.ng, ao, px.perceptualRoughness);
    // 1 - E clamped at 0: the cloth channel exceeds 1 at grazing views (docs/energy.md).
    return diffuse * max(vec3(1.0) - E, 0.0) + mb_fetch_prefiltered(r, lod) * E * occlusion;
#else
    return diffuse;
#endif
}
#endif

vec3 mb_emission(ShadingPixel px) {
    return px.emissive;
}
