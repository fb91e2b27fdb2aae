// A rectangle light's LTC integral (Heitz et al. 2016, section 3.4 and eq. 11): D_M over the
// light's own polygon, after the horizon and support clips (common/ltc.glsl).
float mb_rect_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 toCenter, vec3 halfX, vec3 halfY) {
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, mb_ltc_rect_polygon(toCenter, halfX, halfY));
}
