// The direct form of Walter et al. 2007, eq. 33, as seed 000 writes it:
//   D = alpha^2 / (pi * ((n.h)^2 (alpha^2 - 1) + 1)^2)
// Kept only to show why d_ggx.glsl rewrites it: near n.h = 1 the fp32 sum
// (n.h)^2 (alpha^2 - 1) + 1 cancels to ~alpha^2 with an absolute error of ~1 ulp of 1, which at
// alpha = 0.045^2 (alpha^2 = 4.1e-6) is a relative error of ~1e-2 before squaring.
float mb_d_ggx(Geometry g, float alpha) {
    float a2 = alpha * alpha;
    float f = (a2 - 1.0) * g.NoH * g.NoH + 1.0;
    return a2 / (MB_PI * f * f);
}
