// F0 from the metallic workflow with Filament's reflectance parameter (Filament "Physically
// Based Rendering in Filament", sec. 4.8.3.2, after Lagarde & de Rousiers 2014):
//   F0 = 0.16 reflectance^2 (1 - metallic) + baseColor metallic
// reflectance = 0.5 gives the common 4%.
vec3 mb_f0_metallic_filament(vec3 baseColor, float metallic, float reflectance) {
    return vec3(0.16 * reflectance * reflectance * (1.0 - metallic)) + baseColor * metallic;
}
