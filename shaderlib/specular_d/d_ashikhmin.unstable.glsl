// The direct form of the Ashikhmin velvet NDF as seed 004 writes it, with
// sin^2(theta_h) = 1 - (n.h)^2 and sin^4 formed explicitly. Kept only to show why
// d_ashikhmin.glsl uses |n x h|^2: near n.h = 1 the subtraction cancels in fp32.
float mb_d_ashikhmin(Geometry g, float alpha) {
    float cos2 = g.NoH * g.NoH;
    float sin2 = 1.0 - cos2;
    float a2 = alpha * alpha;
    return (1.0 + 4.0 * exp(-cos2 / (a2 * sin2)) / (sin2 * sin2)) / (MB_PI * (1.0 + 4.0 * a2));
}
