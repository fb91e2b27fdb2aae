// A disk (ellipse) light's LTC integral (Heitz et al. 2016 eq. 11; disks after Heitz & Hill
// 2017): D_M over the ellipse's area-matched 8-gon (common/ltc.glsl, mb_ltc_disk_polygon).
float mb_disk_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 toCenter, vec3 halfX, vec3 halfY) {
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, mb_ltc_disk_polygon(toCenter, halfX, halfY));
}
