// Shared by the Charlie sheen visibility bricks (v_charlie, v_charlie_no_softening).
// Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF", sec. 3: fit of
// ln Lambda(cos theta) for the Charlie distribution,
//   L(x) = a / (1 + b x^c) + d x + e,
//   ln Lambda(cos) = L(cos) for cos < 0.5, 2 L(0.5) - L(1 - cos) otherwise,
// coefficients at r = 0 and r = 1 interpolated with t = 1 - (1 - r)^2 (seed 000 CharlieL).
// The form a/(1 + b x^c) + d x + e is the paper's: against the exact Lambda integral
// (MB_GROUND_TRUTH of v_charlie_no_softening) it is within 3-19% of Lambda for r in [0.1, 1],
// while the other published variant a/((1 + b x^c) + d x + e) is off by 5-14 orders of
// magnitude (e.g. r = 0.5, cos = 0.5: exact 0.875, this form 0.944, the variant 1.6e-9).
float mb_sheen_charlie_L(float x, float r) {
    float t = 1.0 - (1.0 - r) * (1.0 - r);
    float a = mix(25.3245, 21.5473, t);
    float b = mix(3.32435, 3.82987, t);
    float c = mix(0.16801, 0.19823, t);
    float d = mix(-1.27393, -1.97760, t);
    float e = mix(-4.85967, -4.32054, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}

// ln Lambda(cos theta); Lambda itself is exp() of this (kept in log form so that the
// terminator softening Lambda^s is exp(s ln Lambda), not a pow of an exp). makeGeometry's
// n.v can exceed 1 by an ulp (it is only clamped from below); 1 - cos would then be negative
// and pow() of it NaN, so cos is first clamped to its domain [0, 1].
float mb_sheen_charlie_log_lambda(float cosTheta, float r) {
    cosTheta = clamp(cosTheta, 0.0, 1.0);
    return cosTheta < 0.5 ? mb_sheen_charlie_L(cosTheta, r)
                          : 2.0 * mb_sheen_charlie_L(0.5, r) - mb_sheen_charlie_L(1.0 - cosTheta, r);
}
