// A sphere light's LTC integral (Heitz et al. 2016): D_M over the area-matched 8-gon of the
// disk that faces the shading point and subtends the sphere's cap (common/ltc.glsl,
// mb_ltc_sphere_polygon; Heitz & Hill 2017 shade spheres as such disks).
float mb_sphere_ltc_polygon(Geometry g, float m00, float m02, float m20, float m22, vec3 toCenter, float radius) {
    return mb_ltc_integrate(g.n, g.v, m00, m02, m20, m22, mb_ltc_sphere_polygon(g.n, toCenter, radius));
}
