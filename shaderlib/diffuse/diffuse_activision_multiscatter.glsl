// Multiscattering diffuse of Lambertian microfacets (Chan 2018, "Material Advances in Call
// of Duty: WWII", SIGGRAPH Advances course, section 5; seed 000), divided by pi:
//   g  = gloss, from the paper's GGX parameterisation (eq. 2) alpha^2 = 2 / (1 + 2^(18 g)),
//        i.e. g = saturate(log2(2 / alpha^2 - 1) / 18)
//   f0 = l.h + (1 - l.h)^5
//   f1 = (1 - 0.75 (1 - n.l)^5) (1 - 0.75 (1 - n.v)^5)
//   fd = lerp(f0, f1, saturate(2.2 g - 0.5))
//   fb = ((34.5 g - 59) g + 24.5) l.h 2^(-max(73.2 g - 21.2, 8.9) sqrt(n.h))
//   f  = max(fd + fb, 0) / pi
// Gloss mapping: seed 000 writes g = saturate(0.18455 * log(2/alpha^2 - 1)) with HLSL's
// natural log. 0.18455 = 1/(18 log10 2), so that constant belongs with log10; with ln it
// makes g ln(10) = 2.30 times too large: g saturates to 1 already at alpha^2 = 8.8e-3
// (perceptual roughness 0.31) instead of alpha^2 = 2/(2^18 + 1) = 7.6e-6, and at perceptual
// roughness 0.5 gives g = 0.63 instead of 0.28, which moves it to the other end of the fit
// (t = 0.89 instead of 0.11). We follow the paper's eq. 2: g = log2(2/alpha^2 - 1) / 18.
// alpha here is the slot's linear roughness (perceptualRoughness^2), the GGX alpha of eq. 2.
// Stability: all terms are sums of non-negative products except fb < 0 for g in (0.71, 1),
// where fd + fb can cross zero (an absolute, not relative, error there); 2/alpha^2 - 1 >= 1
// for alpha <= 1, so the log2 argument never approaches zero.
float mb_diffuse_activision_multiscatter(Geometry g, float perceptualRoughness, float alpha) {
    float a2 = alpha * alpha;
    float gloss = clamp(log2(2.0 / a2 - 1.0) * (1.0 / 18.0), 0.0, 1.0);
    float f0 = g.LoH + mb_pow5(1.0 - g.LoH);
    float f1 = (1.0 - 0.75 * mb_pow5(1.0 - g.NoL)) * (1.0 - 0.75 * mb_pow5(1.0 - g.NoV));
    float t = clamp(2.2 * gloss - 0.5, 0.0, 1.0);
    float fd = f0 + (f1 - f0) * t;
    float fb = ((34.5 * gloss - 59.0) * gloss + 24.5) * g.LoH *
               exp2(-max(73.2 * gloss - 21.2, 8.9) * sqrt(g.NoH));
    return max(fd + fb, 0.0) * (1.0 / MB_PI);
}
