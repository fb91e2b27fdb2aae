// Fabric Lambert (Unity SRP BSDF.hlsl FabricLambertNoPI; seed 000 "Fabric Material"):
//   f_d = lerp(1, 0.5, alpha) / pi
// with alpha = perceptualRoughness^2. Seed 000 calls FabricLambertDiffuse(roughness, ...)
// and defines "roughness" as alpha = (linear roughness)^2 ("Roughness or Perceptual
// Roughness?"); Unity's Fabric passes roughnessT, also an alpha. A darker Lambert for rough
// cloth; the wrap/subsurface part is the diffuse_wrap slot.
float mb_diffuse_fabric_lambert(Geometry g, float perceptualRoughness, float alpha) {
    return mix(1.0, 0.5, alpha) * (1.0 / MB_PI);
}
