// Separable Schlick-GGX visibility with UE4's direct-lighting k (Karis 2013, "Real Shading in
// Unreal Engine 4", p. 3; Schlick 1994; seeds 002, 003):
//   k = (r + 1)^2 / 8 with r = perceptual roughness = sqrt(alpha),
//   G1(x) = n.x / (n.x (1 - k) + k),   V = G1(l) G1(v) / (4 n.l n.v).
// Stability: the n.l n.v of G1(l) G1(v) is cancelled analytically, giving
//   V = 0.25 / ((n.l (1 - k) + k) (n.v (1 - k) + k)),
// finite at n.l = 0 without seed 003's "+ 0.001" in the denominator (which biases V by up
// to 0.1% / (n.l n.v), i.e. 100% at n.l n.v = 1e-3). k >= 1/8, so the denominator >= 1/64.
float mb_v_schlick_ggx_ue4(Geometry g, float alpha) {
    float r = sqrt(alpha);
    float k = (r + 1.0) * (r + 1.0) * 0.125;
    float gl = g.NoL * (1.0 - k) + k;
    float gv = g.NoV * (1.0 - k) + k;
    return 0.25 / (gl * gv);
}
