// Specular occlusion from ambient occlusion (Lagarde & de Rousiers 2014, "Moving Frostbite to
// PBR", listing 26 computeSpecOcclusion; Filament computeSpecularAO):
//   so = saturate((n.v + ao)^(2^(-16 alpha - 1)) - 1 + ao),  alpha = perceptualRoughness^2
// The base n.v + ao is >= 0, so pow() is defined; the geometric normal is unused.
float mb_so_lagarde(Geometry g, vec3 geometricNormal, float ao, float perceptualRoughness) {
    float alpha = perceptualRoughness * perceptualRoughness;
    return clamp(pow(g.NoV + ao, exp2(-16.0 * alpha - 1.0)) - 1.0 + ao, 0.0, 1.0);
}
