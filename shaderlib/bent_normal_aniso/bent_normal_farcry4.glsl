// Anisotropic bent normal for image-based lighting (McAuley 2015, "Rendering the World of Far
// Cry 4", GDC; Filament getReflectedVector; seed 000 "Anisotropic Specular Material"):
//   direction          = anisotropy >= 0 ? b : t
//   anisotropicTangent = direction x v
//   anisotropicNormal  = anisotropicTangent x direction   (= v minus its part along direction)
//   bend               = |anisotropy| saturate(stretch perceptualRoughness), stretch = 5
//   bentNormal         = normalize(mix(n, anisotropicNormal, bend))
// The environment is then sampled along reflect(-v, bentNormal). Seed 000 calls the roughness
// "linearRoughness"; it is the perceptual roughness (alpha = linearRoughness^2 there).
// Stability: n . anisotropicNormal = n . v exactly (direction is orthogonal to n), so the
// mixed vector has length >= (1 - bend) + bend (n.v) >= n.v > 0 on the front side: the
// normalize never sees a zero vector there. The bend is continuous across anisotropy = 0
// (where direction switches, bend = 0). t is orthonormalized in mb_aniso_tangent.
vec3 mb_bent_normal_farcry4(Geometry g, vec3 t, float anisotropy, float perceptualRoughness) {
    vec3 tangent = mb_aniso_tangent(g.n, t);
    vec3 direction = anisotropy >= 0.0 ? cross(g.n, tangent) : tangent;
    vec3 anisotropicTangent = cross(direction, g.v);
    vec3 anisotropicNormal = cross(anisotropicTangent, direction);
    float bend = abs(anisotropy) * clamp(5.0 * perceptualRoughness, 0.0, 1.0);
    return normalize(mix(g.n, anisotropicNormal, bend));
}
