// Cone-footprint roughness-to-mip mapping (Unity ImageBasedLighting.hlsl, the "accurate"
// PerceptualRoughnessToMipmapLevel(perceptualRoughness, NdotR); seed 000):
//   m = r^2, n = 2/m^2 - 2 (Phong-equivalent exponent), n' = n / (4 n.r),
//   r' = (2 / (n' + 2))^(1/4),  mip = r' maxMip
// Stability: substituting n' gives r'^4 = 4 n.r m^2 / (1 - m^2 + 4 n.r m^2), with no 1/m^2
// (infinite at r = 0) and no 2/m^2 - 2 cancellation near m = 1. Unity guards with
// max(REAL_EPS, m^2) and max(n.r, REAL_EPS); the first changes the mip for r < 0.0186 (up to
// 0.16 mip at maxMip 6) and is not needed here: r = 0 gives the mirror limit 0. n.r >= 1e-4 is
// the domain (at m = 1, n.r = 0 the expression is 0/0). 1 - m^2 = 1 - r^4 cancels as r -> 1
// (measured 5.5e-5 mip at r = 0.9998, n.r = 1e-4); it is formed as (1 - r)(1 + r)(1 + r^2),
// where 1 - r is exact in fp32 (Sterbenz) and the rest are sums of positive terms.
float mb_mip_unity_accurate(float perceptualRoughness, float NoR, float maxMip) {
    float r = perceptualRoughness;
    float m = r * r;
    float m2 = m * m;
    float oneMinusM2 = (1.0 - r) * (1.0 + r) * (1.0 + m);
    float x = 4.0 * NoR * m2;
    float r4 = x / (oneMinusM2 + x);
    return sqrt(sqrt(r4)) * maxMip;
}
