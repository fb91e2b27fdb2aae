// GGX importance sampling of the half vector (Walter et al. 2007 eq. 35-36; Karis 2013 "Real
// Shading in Unreal Engine 4", ImportanceSampleGGX; seed 002): for uniform (u1, u2),
//   phi = 2 pi u1,  cos^2(theta) = (1 - u2) / (1 + (alpha^2 - 1) u2)
// in the tangent frame of UE4's listing (up = |n.z| < 0.999 ? z : x, t = normalize(up x n),
// b = n x t), returned in world space (alpha = linear roughness; UE4's a = Roughness^2).
// Stability: 1 + (a^2 - 1) u2 cancels to (1 - u2) + a^2 u2 as u2 -> 1 (up to 1.5% error at
// alpha = 0.002), and sin = sqrt(1 - cos^2) cancels as cos -> 1. Both are rewritten with the
// exact 1 - u2: den = (1 - u2) + a^2 u2, cos = sqrt((1 - u2)/den), sin = alpha sqrt(u2/den).
vec3 mb_importance_sample_ggx(Geometry g, float u1, float u2, float alpha) {
    float a2 = alpha * alpha;
    float oneMinusU2 = 1.0 - u2;
    float den = oneMinusU2 + a2 * u2;
    float cosTheta = sqrt(oneMinusU2 / den);
    float sinTheta = alpha * sqrt(u2 / den);
    float phi = 2.0 * MB_PI * u1;
    vec3 up = abs(g.n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 tangentX = normalize(cross(up, g.n));
    vec3 tangentY = cross(g.n, tangentX);
    return tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) + g.n * cosTheta;
}
