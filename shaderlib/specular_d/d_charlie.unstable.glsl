// The direct form of Estevez & Kulla 2017 eq. 2 as seed 004 writes it, with
// sin^2(theta_h) = 1 - (n.h)^2. Kept only to show why d_charlie.glsl uses |n x h|^2: near
// n.h = 1 the fp32 subtraction cancels (1 - (n.h)^2 has an absolute error of ~1 ulp of 1).
float mb_d_charlie(Geometry g, float alpha) {
    float sin2 = 1.0 - g.NoH * g.NoH;
    float invAlpha = 1.0 / alpha;
    return (2.0 + invAlpha) * pow(sin2, 0.5 * invAlpha) * (0.5 / MB_PI);
}
