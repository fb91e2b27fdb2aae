// Renormalized Disney diffuse (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically
// Based Rendering 3.0", listing 1; Burley 2012 for the Disney form; seed 000):
//   f_d = (1/pi) * energyFactor * S(n.l) * S(n.v),
//   S(u) = 1 + (fd90 - 1) (1 - u)^5,
//   fd90 = energyBias + 2 (l.h)^2 r,  energyBias = lerp(0, 0.5, r),
//   energyFactor = lerp(1, 1/1.51, r),
// where r is Frostbite's "linearRoughness", i.e. our perceptual roughness.
// Stability: S(u) = 1 - (1-u)^5 + fd90 (1-u)^5 cancels for small u when fd90 is small
// (1 - (1-u)^5 ~ 5u). It is evaluated as u (1 + m + m^2 + m^3 + m^4) + fd90 m^5 with
// m = 1 - u (the geometric-series factorisation of 1 - m^5), which has no cancellation.
float mb_diffuse_disney_renormalized_scatter(float u, float fd90) {
    float m = 1.0 - u;
    float m2 = m * m;
    float oneMinusM5 = u * (1.0 + m + m2 + m2 * m + m2 * m2);
    return oneMinusM5 + fd90 * (m2 * m2 * m);
}

float mb_diffuse_disney_renormalized(Geometry g, float perceptualRoughness, float alpha) {
    float r = perceptualRoughness;
    float energyBias = 0.5 * r;
    float energyFactor = mix(1.0, 1.0 / 1.51, r);
    float fd90 = energyBias + 2.0 * g.LoH * g.LoH * r;
    float lightScatter = mb_diffuse_disney_renormalized_scatter(g.NoL, fd90);
    float viewScatter = mb_diffuse_disney_renormalized_scatter(g.NoV, fd90);
    return lightScatter * viewScatter * energyFactor * (1.0 / MB_PI);
}
