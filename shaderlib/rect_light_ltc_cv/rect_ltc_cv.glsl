// A rectangle light's specular lobe integral by linearly transformed cosines with a control
// variate: norm Int D_M over its polygon (Heitz et al. 2016) plus what D_M misses of the lobe,
// by a fan quadrature over the same polygon (common/ltc.glsl, mb_ltc_lobe_cv; why:
// docs/models/lights.md, "Rectangle and disk lights").
float mb_rect_ltc_cv(Geometry g, float alpha, float norm, float m00, float m02, float m20, float m22, vec3 toCenter,
                     vec3 halfX, vec3 halfY) {
    return mb_ltc_lobe_cv(MB_LTC_LOBE_GGX, g.n, g.v, alpha, norm, m00, m02, m20, m22, mb_ltc_rect_polygon(toCenter, halfX, halfY));
}
