// Lambertian diffuse (Lambert 1760; Karis 2013 "Real Shading in Unreal Engine 4", p. 2, seed
// 002; seed 003):  f_d = 1 / pi  (the model multiplies by diffuseColor).
float mb_diffuse_lambert(Geometry g, float perceptualRoughness, float alpha) {
    return 1.0 / MB_PI;
}
