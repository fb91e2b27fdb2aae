// A tube (capsule) light's specular lobe integral by linearly transformed cosines with a control
// variate over the capsule's silhouette polygon (common/ltc.glsl, mb_ltc_lobe_cv; as
// sphere_ltc_cv).
float mb_tube_ltc_cv(Geometry g, float alpha, float norm, float m00, float m02, float m20, float m22, vec3 L0, vec3 L1,
                     float radius) {
    return mb_ltc_lobe_cv(MB_LTC_LOBE_GGX, g.n, g.v, alpha, norm, m00, m02, m20, m22, mb_ltc_tube_polygon(g.n, L0, L1, radius));
}
