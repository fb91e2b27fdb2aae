// F0 from the metallic workflow with a fixed dielectric 4% (seed 003 Calculate_F0, Unity and
// UE4 convention): F0 = lerp(0.04, baseColor, metallic). reflectance is unused.
vec3 mb_f0_metallic_lerp(vec3 baseColor, float metallic, float reflectance) {
    return mix(vec3(0.04), baseColor, metallic);
}
