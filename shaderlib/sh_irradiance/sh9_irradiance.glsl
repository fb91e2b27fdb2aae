// Irradiance from 9 spherical-harmonic radiance coefficients (Ramamoorthi & Hanrahan 2001,
// "An Efficient Representation for Irradiance Environment Maps", eq. 13; seed 003 SampleSH9):
//   E(n) = c1 L22 (x^2 - y^2) + c3 L20 z^2 + c4 L00 - c5 L20
//        + 2 c1 (L2-2 xy + L21 xz + L2-1 yz) + 2 c2 (L11 x + L1-1 y + L10 z)
// c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708 (given here to
// full fp32 precision from their definitions, e.g. c4 = pi * Y00 = sqrt(pi)/2).
// Coefficients sh0..sh8 = L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (index l(l+1)+m) of
// the radiance projected on the real SH basis; returns irradiance E (not divided by pi).
vec3 mb_sh9_irradiance(vec3 n, vec3 sh0, vec3 sh1, vec3 sh2, vec3 sh3, vec3 sh4, vec3 sh5,
                       vec3 sh6, vec3 sh7, vec3 sh8) {
    const float c1 = 0.42904276540489171;
    const float c2 = 0.51166335397324424;
    const float c3 = 0.74312830170378928;
    const float c4 = 0.88622692545275801;
    const float c5 = 0.24770943390126310;
    vec3 d = normalize(n);
    return c1 * sh8 * (d.x * d.x - d.y * d.y) + c3 * sh6 * (d.z * d.z) + c4 * sh0 - c5 * sh6 +
           2.0 * c1 * (sh4 * (d.x * d.y) + sh7 * (d.x * d.z) + sh5 * (d.y * d.z)) +
           2.0 * c2 * (sh3 * d.x + sh1 * d.y + sh2 * d.z);
}
