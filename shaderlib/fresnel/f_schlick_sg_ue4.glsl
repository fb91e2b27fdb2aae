// Schlick Fresnel with UE4's spherical-Gaussian replacement of the power (Karis 2013, "Real
// Shading in Unreal Engine 4", p. 3, after Lagarde 2012; seed 002):
//   F = f0 + (f90 - f0) 2^((-5.55473 v.h - 6.98316) v.h)
// (seed 002 writes f90 = 1). The exponent is a product of bounded terms, no cancellation.
vec3 mb_f_schlick_sg_ue4(Geometry g, vec3 f0, float f90) {
    float w = exp2((-5.55473 * g.VoH - 6.98316) * g.VoH);
    return f0 + (vec3(f90) - f0) * w;
}
