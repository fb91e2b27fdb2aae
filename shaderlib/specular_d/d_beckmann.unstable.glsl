// The direct Beckmann form with tan^2(theta_h) = (1 - (n.h)^2) / (n.h)^2. Kept only to show
// why d_beckmann.glsl uses |n x h|^2: near n.h = 1 at low roughness the fp32 subtraction
// cancels, and exp(-tan^2 / alpha^2) amplifies its error by 1 / alpha^2.
float mb_d_beckmann(Geometry g, float alpha) {
    float cos2 = g.NoH * g.NoH;
    float a2 = alpha * alpha;
    float tan2 = (1.0 - cos2) / cos2;
    return exp(-tan2 / a2) / (MB_PI * a2 * cos2 * cos2);
}
