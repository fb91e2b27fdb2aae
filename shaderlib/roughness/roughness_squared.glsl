// UE4 / Disney roughness remap (Karis 2013, "Real Shading in Unreal Engine 4", p. 3; seed 002):
//   alpha = roughness^2
// One multiplication: no cancellation, exact up to one rounding.
float mb_roughness_squared(float perceptualRoughness) {
    return perceptualRoughness * perceptualRoughness;
}
