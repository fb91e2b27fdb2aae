// Horizon specular occlusion (Russell 2014, Marmoset "Horizon Occlusion for Normal Mapped
// Reflections"; seed 000 "Specular Miscs"): a reflection vector bent below the geometric
// surface by the normal map is faded out,
//   r = reflect(-v, n),  h = saturate(1 + 1.3 r.n_geometric),  occlusion = h^2
// with Marmoset's horizonFade = 1.3. ao and perceptualRoughness are unused.
float mb_so_horizon_marmoset(Geometry g, vec3 geometricNormal, float ao, float perceptualRoughness) {
    vec3 r = reflect(-g.v, g.n);
    float horizon = clamp(1.0 + 1.3 * dot(r, normalize(geometricNormal)), 0.0, 1.0);
    return horizon * horizon;
}
