// Standard shading model skeleton: diffuse + Cook-Torrance specular (seed 000 "BRDF
// Assembly", seed 002 "Shading Model"). The emitter binds each MB_SLOT_<slot> macro to the
// brick the material picked, so the skeleton never names a brick.
// F0 = mix(0.04, baseColor, metallic) and diffuseColor = baseColor * (1 - metallic) (seed 003).

struct MaterialInputs {
    vec3 baseColor;
    float metallic;
    float roughness;  // perceptual roughness
};

// BRDF times n.l times the light's illuminance, for one light direction.
vec3 mb_standard_direct(MaterialInputs m, Geometry g, vec3 illuminance) {
    float perceptualRoughness = m.roughness;
    float alpha = MB_SLOT_roughness(perceptualRoughness);
    vec3 f0 = mix(vec3(0.04), m.baseColor, m.metallic);
    vec3 diffuseColor = m.baseColor * (1.0 - m.metallic);

    float D = MB_SLOT_specular_d(g, alpha);
    float V = MB_SLOT_specular_v(g, alpha);
    vec3 F = MB_SLOT_fresnel(g, f0, 1.0);
    // n.l multiplies V before D: at fp16, D and V near a grazing, sharp peak each fit in half
    // but D * V does not, and (D * V) * n.l would give Inf * 0 = NaN where n.l = 0.
    float specular = D * (V * g.NoL);
#ifdef MB_FP16
    // Filament's saturateMediump: the per-unit-illuminance specular is clamped to the largest
    // half (65504) so that a dim light (illuminance < 1) times a peak too bright for half at
    // unit illuminance stays finite; Inf remains only where the exact radiance overflows half.
    specular = min(specular, 65504.0);
#endif
    vec3 Fr = specular * F;
    vec3 Fd = diffuseColor * (MB_SLOT_diffuse(g, perceptualRoughness, alpha) * g.NoL);
    return (Fd + Fr) * illuminance;
}

// Outgoing radiance towards v. `l` points to the light; `illuminance` is its colour times
// intensity at the surface.
vec3 mb_standard_evaluate(MaterialInputs m, vec3 n, vec3 v, vec3 l, vec3 illuminance) {
    Geometry g = makeGeometry(n, v, l);
    vec3 color = vec3(0.0);
    // [lights] punctual and area lights are added here (issue: complete standard model).
    color += mb_standard_direct(m, g, illuminance);
    // [ibl] indirect diffuse (SH9) and specular (prefiltered env + DFG) go here.
    // [layers] clear coat attenuation of the base goes here.
    return color;
}
