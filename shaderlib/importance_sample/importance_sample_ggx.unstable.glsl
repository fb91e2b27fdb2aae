// ImportanceSampleGGX as Karis 2013 (seed 002) writes it:
//   cos = sqrt((1 - u2) / (1 + (a^2 - 1) u2)),  sin = sqrt(1 - cos^2)
// Kept only to show why importance_sample_ggx.glsl rewrites it: 1 + (a^2 - 1) u2 cancels as
// u2 -> 1 at low roughness, and sqrt(1 - cos^2) cancels as cos -> 1.
vec3 mb_importance_sample_ggx(Geometry g, float u1, float u2, float alpha) {
    float a2 = alpha * alpha;
    float cosTheta = sqrt((1.0 - u2) / (1.0 + (a2 - 1.0) * u2));
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    float phi = 2.0 * MB_PI * u1;
    vec3 up = abs(g.n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 tangentX = normalize(cross(up, g.n));
    vec3 tangentY = cross(g.n, tangentX);
    return tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) + g.n * cosTheta;
}
