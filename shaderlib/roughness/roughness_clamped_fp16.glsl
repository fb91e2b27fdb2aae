// Filament roughness remap with the fp16 floor (Filament "Physically Based Rendering in
// Filament", sec. 4.8.3.3, MIN_PERCEPTUAL_ROUGHNESS = 0.089 on mobile; seed 000 "Specular
// Miscs"): alpha = clamp(perceptualRoughness, 0.089, 1)^2. 0.089^4 = 6.27e-5 keeps alpha^2
// above fp16's smallest normal (6.1e-5), so 1/alpha^2 terms stay finite in half precision.
float mb_roughness_clamped_fp16(float perceptualRoughness) {
    float r = clamp(perceptualRoughness, 0.089, 1.0);
    return r * r;
}
