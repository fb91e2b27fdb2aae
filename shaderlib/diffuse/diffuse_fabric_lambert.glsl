// Fabric Lambert (Unity HDRP FabricLambert, BSDF.hlsl; seed 000 "Fabric Material"):
//   f_d = lerp(1, 0.5, r) / pi
// with r the perceptual roughness (seed 000 passes its "roughness" texture value). A darker
// Lambert for rough cloth; the wrap/subsurface part is the diffuse_wrap slot.
float mb_diffuse_fabric_lambert(Geometry g, float perceptualRoughness, float alpha) {
    return mix(1.0, 0.5, perceptualRoughness) * (1.0 / MB_PI);
}
