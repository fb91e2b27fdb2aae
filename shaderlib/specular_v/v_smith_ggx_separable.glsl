// Separable (uncorrelated) Smith-GGX visibility (Smith 1967; Walter et al. 2007 eq. 34;
// Heitz 2014 eq. 98): V = G1(l) G1(v) / (4 n.l n.v), G1(x) = 2 n.x / (n.x + sqrt(a^2 + (1-a^2) n.x^2)).
// The n.l n.v cancels analytically:
//   V = 1 / ((n.v + sqrt(a^2 + (1-a^2) n.v^2)) (n.l + sqrt(a^2 + (1-a^2) n.l^2)))
// finite at n.l = 0 (1 / (alpha (n.v + ...))); sums of non-negative terms.
float mb_v_smith_ggx_separable(Geometry g, float alpha) {
    float a2 = alpha * alpha;
    float sv = g.NoV + sqrt(a2 + (1.0 - a2) * g.NoV * g.NoV);
    float sl = g.NoL + sqrt(a2 + (1.0 - a2) * g.NoL * g.NoL);
    return 1.0 / (sv * sl);
}
