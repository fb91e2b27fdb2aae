// Base roughness under a clear coat, KHR_materials_clearcoat: unchanged. glTF layers the coat
// over the base material with fresnel_coat and leaves the base's parameters as they are.
float mb_coat_base_roughness_keep(float perceptualRoughness, float clearCoatRoughness, float clearCoat) {
    return perceptualRoughness;
}
