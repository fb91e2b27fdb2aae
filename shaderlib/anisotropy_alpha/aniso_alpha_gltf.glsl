// Anisotropic alphas of KHR_materials_anisotropy (section "Anisotropy"):
//   alpha_t = mix(alpha, 1, s^2),  alpha_b = alpha
// glTF stretches the lobe only along the anisotropy direction (the engine's tangent t), up to
// alpha 1 at strength s = 1; the bitangent keeps the material's alpha.
vec3 mb_aniso_alpha_gltf(float alpha, float anisotropy) {
    return vec3(mix(alpha, 1.0, anisotropy * anisotropy), alpha, 0.0);
}
