// Filament roughness remap with the fp32 floor (Filament "Physically Based Rendering in
// Filament", section 4.8.3.3 / MIN_PERCEPTUAL_ROUGHNESS; seed 000 "Specular Miscs"):
//   alpha = clamp(perceptualRoughness, 0.045, 1)^2
// 0.045^2 = 0.002025 keeps alpha^2 = 4.1e-6 (and the GGX peak 1/(pi alpha^2)) well inside
// fp32; the clamp is part of the published definition, not a numerical patch.
float mb_roughness_clamped(float perceptualRoughness) {
    float r = clamp(perceptualRoughness, 0.045, 1.0);
    return r * r;
}
