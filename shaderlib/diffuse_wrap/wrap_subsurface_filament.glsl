// Energy-conserving wrap diffuse with subsurface colour, for cloth (Filament "Physically
// Based Rendering in Filament", sec. 4.12.2 "Cloth diffuse", after Green 2004; seed 000
// "Fabric Material"):
//   factor = saturate((n.l + w) / (1 + w)^2) * saturate(subsurfaceColor + n.l)
// with the *signed* n.l (back-lit points get light through the wrap), so it is taken from the
// vectors, not from g.NoL (clamped to [0, 1]). Seed 000 hard-codes w = 0.5: (1 + w)^2 = 2.25.
// Replaces saturate(n.l) in the diffuse term. Sums of bounded terms: no cancellation.
vec3 mb_wrap_subsurface_filament(Geometry g, float wrap, vec3 subsurfaceColor) {
    float NoL = dot(g.n, g.l);
    float onePlusW = 1.0 + wrap;
    float wrapped = clamp((NoL + wrap) / (onePlusW * onePlusW), 0.0, 1.0);
    return wrapped * clamp(subsurfaceColor + vec3(NoL), 0.0, 1.0);
}
