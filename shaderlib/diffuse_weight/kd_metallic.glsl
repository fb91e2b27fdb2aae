// Diffuse weight without Fresnel coupling: kD = 1 - metallic (Filament sec. 4.8.3.2,
// diffuseColor = (1 - metallic) baseColor; Karis 2013 "Material Model"). F is unused.
vec3 mb_kd_metallic(vec3 F, float metallic) {
    return vec3(1.0 - metallic);
}
