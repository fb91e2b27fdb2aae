// Anisotropic height-correlated Smith visibility for GGX (Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs", eqs. 86 and 99; Filament
// surface_brdf.fs, V_SmithGGXCorrelated_Anisotropic):
//   Lambda(w) = (-1 + sqrt(1 + ((at t.w)^2 + (ab b.w)^2) / (n.w)^2)) / 2
//   V = G2 / (4 n.l n.v) = 0.5 / (n.l |(at t.v, ab b.v, n.v)| + n.v |(at t.l, ab b.l, n.l)|)
// The 4 n.l n.v is cancelled analytically against 1 + Lambda(v) + Lambda(l), so V is finite
// at n.l = 0 (0.5 / (n.v |(at t.l, ab b.l)|)) with no epsilon; every term is a non-negative
// sum: no cancellation. The interpolated tangent t is orthonormalized in mb_aniso_tangent.
float mb_v_smith_ggx_correlated_aniso(Geometry g, vec3 t, float at, float ab) {
    vec3 tangent = mb_aniso_tangent(g.n, t);
    vec3 bitangent = cross(g.n, tangent);
    float lambdaV = g.NoL * length(vec3(at * dot(tangent, g.v), ab * dot(bitangent, g.v), g.NoV));
    vec2 lt = mb_aniso_light_tangent(g, tangent, bitangent);  // l below the horizon: see aniso.glsl
    float lambdaL = g.NoV * length(vec3(at * lt.x, ab * lt.y, g.NoL));
    return 0.5 / (lambdaV + lambdaL);
}
