// Base roughness under a clear coat (seed 000 "Clear Coating Material", after Filament sec.
// 4.9.3): r' = lerp(r, max(r, r_c), c). The seed's "linear" roughness is the perceptual one.
float mb_coat_base_roughness_max(float perceptualRoughness, float clearCoatRoughness, float clearCoat) {
    return mix(perceptualRoughness, max(perceptualRoughness, clearCoatRoughness), clearCoat);
}
