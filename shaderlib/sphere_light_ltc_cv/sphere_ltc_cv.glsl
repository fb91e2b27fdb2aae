// A sphere light's specular lobe integral by linearly transformed cosines with a control
// variate: norm Int D_M over the cap's 8-gon (Heitz et al. 2016) plus what D_M misses of the
// lobe, Int (lobe - norm D_M), by a fan quadrature over the same polygon (common/ltc.glsl,
// mb_ltc_lobe_cv; why: docs/models/lights.md, "LTC against the brute-force integral").
float mb_sphere_ltc_cv(Geometry g, float alpha, float norm, float m00, float m02, float m20, float m22, vec3 toCenter,
                       float radius) {
    return mb_ltc_lobe_cv(MB_LTC_LOBE_GGX, g.n, g.v, alpha, norm, m00, m02, m20, m22, mb_ltc_sphere_polygon(g.n, toCenter, radius));
}
