// A tube (capsule) light's LTC integral (Heitz et al. 2016): D_M over the capsule's silhouette
// polygon (common/ltc.glsl, mb_ltc_tube_polygon).
float mb_tube_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 L0, vec3 L1, float radius) {
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, mb_ltc_tube_polygon(g.n, L0, L1, radius));
}
