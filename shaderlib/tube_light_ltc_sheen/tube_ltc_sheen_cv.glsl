// The sheen lobe's integral over a tube (capsule) light, as its silhouette polygon, by linearly transformed cosines fitted to it
// (shaderlib/ltc/charlie.json) with a control variate: norm Int D_M plus the residual's fan
// quadrature in the LTC's space (common/ltc.glsl, mb_ltc_lobe_cv with the Charlie lobe; why:
// docs/models/lights.md, "Sheen by LTC").
float mb_tube_ltc_sheen_cv(Geometry g, float alpha, float norm, float m00, float m02, float m20, float m22, vec3 L0, vec3 L1, float radius) {
    return mb_ltc_lobe_cv(MB_LTC_LOBE_CHARLIE, g.n, g.v, alpha, norm, m00, m02, m20, m22,
                          mb_ltc_tube_polygon(g.n, L0, L1, radius));
}
