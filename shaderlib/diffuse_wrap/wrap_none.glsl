// No wrap: the clamped cosine saturate(n.l) of the rendering equation (seed 000 "Fabric
// Material", the term the wrap replaces). wrap and subsurfaceColor are unused.
vec3 mb_wrap_none(Geometry g, float wrap, vec3 subsurfaceColor) {
    return vec3(g.NoL);
}
