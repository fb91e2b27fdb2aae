// GGX / Trowbridge-Reitz NDF in the tan^2 form of pbrt-v4 (TrowbridgeReitzDistribution::D),
// multiplied through by cos^4: D(h) = alpha^2 / (pi (cos^2 alpha^2 + sin^2)^2), with sin^2
// taken as |n x h|^2 so that it does not cancel near n.h = 1. A test brick: it stands for a
// new D added to shaderlib/specular_d/ (tests/test_brick_data.cpp).
float mb_d_ggx_tan2(Geometry g, float alpha) {
    vec3 nxh = cross(g.n, g.h);
    float sin2 = dot(nxh, nxh);
    float a2 = alpha * alpha;
    float e = g.NoH * g.NoH * a2 + sin2;
    return a2 / (MB_PI * e * e);
}
