// Original Disney diffuse (Burley 2012, "Physically-Based Shading at Disney", sec. 5.3):
//   f_d = (1/pi) (1 + (F_D90 - 1)(1 - n.l)^5) (1 + (F_D90 - 1)(1 - n.v)^5),
//   F_D90 = 0.5 + 2 r (l.h)^2,  r = perceptual roughness.
// Not energy conserving (reflects up to ~1.5x at grazing, rough); see the Frostbite
// renormalized brick. Stability: each factor S(u) = 1 - (1-u)^5 + F_D90 (1-u)^5 is evaluated
// as u (1 + m + m^2 + m^3 + m^4) + F_D90 m^5, m = 1 - u, to avoid the cancellation of
// 1 - (1-u)^5 at small u (the same rewrite as diffuse_disney_renormalized).
float mb_diffuse_disney_burley_scatter(float u, float fd90) {
    float m = 1.0 - u;
    float m2 = m * m;
    return u * (1.0 + m + m2 + m2 * m + m2 * m2) + fd90 * (m2 * m2 * m);
}

float mb_diffuse_disney_burley(Geometry g, float perceptualRoughness, float alpha) {
    float fd90 = 0.5 + 2.0 * perceptualRoughness * g.LoH * g.LoH;
    return mb_diffuse_disney_burley_scatter(g.NoL, fd90) *
           mb_diffuse_disney_burley_scatter(g.NoV, fd90) * (1.0 / MB_PI);
}
