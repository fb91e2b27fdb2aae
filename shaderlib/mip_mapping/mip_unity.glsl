// Unity's roughness-to-mip curve (Unity ImageBasedLighting.hlsl PerceptualRoughnessToMipmapLevel;
// seed 000): mip = r (1.7 - 0.7 r) maxMip. It matches the cone-footprint mapping at n.r = 1
// (r sqrt(2) / (1 + 3 r^4)^(1/4): 0.675 vs 0.677 at r = 0.5). NoR is unused.
float mb_mip_unity(float perceptualRoughness, float NoR, float maxMip) {
    float r = perceptualRoughness;
    return r * (1.7 - 0.7 * r) * maxMip;
}
