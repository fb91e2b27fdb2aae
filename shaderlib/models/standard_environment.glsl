// Standard model: environment light (docs/models/environment.md). Included after
// standard.glsl. Three modes besides none:
//   sh           diffuse only: diffuseColor * E(n) / pi * ao, E the SH9 irradiance (seed 003
//                SampleSH9; Ramamoorthi & Hanrahan 2001). No specular: SH9 cannot hold a
//                glossy reflection.
//   ibl_lut      split sum (Karis 2013, seed 002 / seed 000 "Indirect Specular"):
//                prefiltered(r, lod) * DFG(f0) * energy compensation * specular occlusion,
//                DFG from the LUT texel (DESIGN.md convention: x = Int Gv Fc, y = Int Gv).
//   ibl_analytic the same with an analytic env BRDF in place of the LUT.
// In both IBL modes the diffuse is weighted by 1 - E, E the specular's directional albedo
// (the env BRDF value): seed 000 weights its indirect diffuse by the complement of
// F_SchlickRoughness, Filament by 1 - specularDFG; the split-sum E is the better estimate of
// the same quantity. The diffuse uses the irradiance as it is (a Lambertian lobe): the
// diffuse brick of direct light is not applied (Filament does the same).

#ifdef MB_ENV_IBL
// The DFG terms at (n.v, perceptual roughness) and the multiscatter factor of the specular
// lobes (seed 000 CompensateDirectBRDF: 1 + f0 (1 / Int Gv - 1)).
void mb_environment_prepare(inout ShadingPixel px, ShadingFrame f) {
#ifdef MB_ENV_IBL_LUT
    px.dfg = mb_fetch_dfg(px.NoV, px.perceptualRoughness);
#else
    // An env BRDF affine in f0 is f0 A + B, so its values at f0 = 0 and f0 = 1 are the two DFG
    // channels B = Int Gv Fc and A + B = Int Gv (docs/models/environment.md lists which bricks
    // are affine).
    px.dfg = vec3(MB_SLOT_env_brdf(vec3(0.0), px.perceptualRoughness, px.NoV).x,
                  MB_SLOT_env_brdf(vec3(1.0), px.perceptualRoughness, px.NoV).x, 0.0);
#endif
    px.energyCompensation = MB_SLOT_energy_compensation(px.f0, px.dfg.y);
}
#endif

#ifndef MB_ENV_NONE
vec3 mb_shade_environment(ShadingPixel px, ShadingFrame f, Environment env) {
    float ao = env.ao * px.ambientOcclusion;
    vec3 diffuse = mb_sh_diffuse(px.diffuseColor, f.n, env, ao);  // common/sh_diffuse.glsl
#ifdef MB_ENV_IBL
    // Mirror direction about the shading normal, or about the Far Cry 4 bent normal of an
    // anisotropic surface (seed 000 "Anisotropic").
    vec3 reflectNormal = f.n;
#ifdef MB_FEATURE_ANISOTROPY
    reflectNormal = mb_anisotropy_ibl_normal(px.anisotropy, f, px.perceptualRoughness);
#endif
    vec3 r = reflect(-f.v, reflectNormal);
    // n.r for the footprint-aware mip mapping (Unity PerceptualRoughnessToMipmapLevel clamps
    // it away from 0 too); the same floor as n.v.
    float NoR = clamp(dot(f.n, r), MB_MIN_N_DOT_V, 1.0);
    float lod = MB_SLOT_mip_mapping(px.perceptualRoughness, NoR, env.maxMip);
#ifdef MB_ENV_IBL_LUT
    vec3 E = MB_SLOT_dfg_lut(px.f0, px.dfg.x, px.dfg.y);
#else
    vec3 E = MB_SLOT_env_brdf(px.f0, px.perceptualRoughness, px.NoV);
#endif
    // Horizon occlusion against the geometric normal (seed 000 "Specular Miscs").
    float occlusion = MB_SLOT_specular_occlusion(makeGeometry(f.n, f.v, r), f.ng, ao, px.perceptualRoughness);
    vec3 specular = mb_fetch_prefiltered(r, lod) * E * px.energyCompensation * occlusion;
    // The diffuse keeps what the specular does not reflect, never less than nothing: E is a
    // directional albedo (<= 1), but a LUT or fit can exceed 1 (a UE4 scale/bias texel with
    // f0 * scale + bias > 1), and 1 - E < 0 would make the radiance negative (issue 18).
    vec3 color = diffuse * max(vec3(1.0) - E, 0.0) + specular;
    // Layers in the order of direct light (standard.glsl): sheen over the base, coat over both.
#ifdef MB_FEATURE_SHEEN
    color = color * px.sheen.scaling + mb_sheen_environment(px.sheen, f, env);
#endif
#ifdef MB_FEATURE_CLEARCOAT
    float coatAttenuation;
    vec3 coat = mb_clearcoat_environment(px.clearCoat, f, env, coatAttenuation);
    color = color * coatAttenuation + coat;
#endif
    return color;
#else
    return diffuse;
#endif
}
#endif
