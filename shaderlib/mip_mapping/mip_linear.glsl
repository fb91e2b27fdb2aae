// Linear roughness-to-mip mapping (seed 000 "Indirect Specular": "mip = linearRoughness *
// maxMip"): mip = r * maxMip, r = perceptual roughness. NoR is unused.
float mb_mip_linear(float perceptualRoughness, float NoR, float maxMip) {
    return perceptualRoughness * maxMip;
}
