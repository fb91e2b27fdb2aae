// Crytek's roughness remap (CryEngine 3, cited in Lagarde & de Rousiers 2014, "Moving
// Frostbite to PBR", sec. 3.2.1 and fig. 12; seed 000 "Roughness or Perceptual Roughness?"):
//   alpha^2 = (1 - 0.7 smoothness)^6,  smoothness = 1 - perceptualRoughness
// so alpha = (1 - 0.7 smoothness)^3 (no sqrt of the sixth power; the base is >= 0.3, so no
// pow of a negative number). Stability: 1 - 0.7 (1 - r) cancels from ~1 down to 0.3 at small r
// (2e-7 relative, 6e-7 after the cube, measured); the algebraically equal 0.3 + 0.7 r has no
// cancellation.
float mb_roughness_crytek(float perceptualRoughness) {
    float base = 0.3 + 0.7 * perceptualRoughness;
    return base * base * base;
}
