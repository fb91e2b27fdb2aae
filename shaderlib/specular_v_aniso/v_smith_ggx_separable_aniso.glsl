// Anisotropic separable Smith visibility for GGX (Burley 2012, "Physically-Based Shading at
// Disney", appendix B.2, smithG_GGX_aniso; Heitz 2014 eqs. 86 and 98): G2 = G1(v) G1(l) with
// G1(w) = 1 / (1 + Lambda(w)) = 2 n.w / (n.w + |(at t.w, ab b.w, n.w)|), so
//   V = G1(v) G1(l) / (4 n.l n.v) = 1 / ((n.v + |(at t.v, ab b.v, n.v)|) (n.l + |(at t.l, ab b.l, n.l)|))
// The n.l n.v is cancelled analytically: finite at n.l = 0; all terms non-negative.
// Approximates the height-correlated form (ground truth: v_smith_ggx_correlated_aniso's).
float mb_v_smith_ggx_separable_aniso(Geometry g, vec3 t, float at, float ab) {
    vec3 tangent = mb_aniso_tangent(g.n, t);
    vec3 bitangent = cross(g.n, tangent);
    float maskV = g.NoV + mb_aniso_length(vec3(at * dot(tangent, g.v), ab * dot(bitangent, g.v), g.NoV));
    vec2 lt = mb_aniso_light_tangent(g, tangent, bitangent);  // l below the horizon: see aniso.glsl
    float maskL = g.NoL + mb_aniso_length(vec3(at * lt.x, ab * lt.y, g.NoL));
#ifdef MB_FP16
    // Half precision: maskV * maskL underflows at grazing angles (a denormal whose
    // reciprocal overflows) where V is in range; dividing by each factor in turn is the same
    // number in real arithmetic, and maskV >= n.v >= 1e-4.
    return 1.0 / maskV / maskL;
#endif
    return 1.0 / (maskV * maskL);
}
