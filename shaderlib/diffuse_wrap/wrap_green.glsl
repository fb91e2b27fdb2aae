// Wrap lighting (Green 2004, "Real-Time Approximations to Subsurface Scattering", GPU Gems
// ch. 16, sec. 16.2): factor = max(0, (n.l + w) / (1 + w)), with the signed n.l taken from the
// vectors. Not energy conserving (the Filament variant divides by (1 + w)^2). subsurfaceColor
// is unused.
vec3 mb_wrap_green(Geometry g, float wrap, vec3 subsurfaceColor) {
    float NoL = dot(g.n, g.l);
    return vec3(max(0.0, (NoL + wrap) / (1.0 + wrap)));
}
