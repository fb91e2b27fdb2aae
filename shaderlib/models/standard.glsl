// Standard shading model skeleton: diffuse + Cook-Torrance specular (seed 000 "BRDF
// Assembly", seed 002 "Shading Model"). The emitter binds each MB_SLOT_<slot> macro to the
// brick the material picked, so the skeleton never names a brick.
// F0 = mix(0.04, baseColor, metallic) and diffuseColor = baseColor * (1 - metallic) (seed 003).

struct MaterialInputs {
    vec3 baseColor;
    float metallic;
    float roughness;  // perceptual roughness
};

// BRDF times n.l for one light direction, per unit illuminance.
vec3 mb_standard_direct(MaterialInputs m, Geometry g) {
    float perceptualRoughness = m.roughness;
    float alpha = MB_SLOT_roughness(perceptualRoughness);
    vec3 f0 = mix(vec3(0.04), m.baseColor, m.metallic);
    vec3 diffuseColor = m.baseColor * (1.0 - m.metallic);

    float D = MB_SLOT_specular_d(g, alpha);
    float V = MB_SLOT_specular_v(g, alpha);
    vec3 F = MB_SLOT_fresnel(g, f0, 1.0);
    vec3 Fr = (D * V) * F;
    vec3 Fd = diffuseColor * MB_SLOT_diffuse(g, perceptualRoughness, alpha);
    return (Fd + Fr) * g.NoL;
}

// Outgoing radiance towards v. `l` points to the light; `illuminance` is its colour times
// intensity at the surface.
vec3 mb_standard_evaluate(MaterialInputs m, vec3 n, vec3 v, vec3 l, vec3 illuminance) {
    Geometry g = makeGeometry(n, v, l);
    vec3 color = vec3(0.0);
    // [lights] punctual and area lights are added here (issue: complete standard model).
    color += mb_standard_direct(m, g) * illuminance;
    // [ibl] indirect diffuse (SH9) and specular (prefiltered env + DFG) go here.
    // [layers] clear coat attenuation of the base goes here.
    return color;
}
