// The sheen lobe's integral over a sphere light, as its cap's 8-gon, by linearly transformed cosines fitted to it
// (shaderlib/ltc/charlie.json) with a control variate: norm Int D_M plus the residual's fan
// quadrature in the LTC's space (common/ltc.glsl, mb_ltc_lobe_cv with the Charlie lobe; why:
// docs/models/lights.md, "Sheen by LTC").
float mb_sphere_ltc_sheen_cv(Geometry g, float alpha, float norm, float m00, float m02, float m20, float m22, vec3 toCenter, float radius) {
    return mb_ltc_lobe_cv(MB_LTC_LOBE_CHARLIE, g.n, g.v, alpha, norm, m00, m02, m20, m22,
                          mb_ltc_sphere_polygon(g.n, toCenter, radius));
}
