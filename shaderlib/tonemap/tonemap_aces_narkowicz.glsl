// ACES filmic tone curve, Narkowicz's fit (Narkowicz 2015, "ACES Filmic Tone Mapping Curve",
// knarkowicz.wordpress.com): a per-channel rational fit to the luminance of ODT(RRT(x)) for a
// Rec.709 display, pre-exposed so that 1 maps to ~0.8 (the original curve is f(0.6 x)):
//   f(x) = saturate(x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14))
// Stability: the denominator has no real root (0.59^2 < 4 * 2.43 * 0.14), so it is >= 0.104
// for every x; for x >= 0 numerator and denominator are sums of non-negative terms.
vec3 mb_tonemap_aces_narkowicz(vec3 color) {
    vec3 x = color;
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
