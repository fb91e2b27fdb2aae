// "Charlie" sheen NDF (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF",
// eq. 2; seeds 000 and 004):
//   D(h) = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi) = (2 + 1/alpha) exp(ln(sin^2) / (2 alpha)) / (2 pi)
// Stability: the power is taken through ln(sin^2 theta_h), whose fp32 error is then
// multiplied by 1/(2 alpha) (up to 2e6 at the 1024^2 LUT's smoothest row). So ln(sin^2) must be
// accurate *relative to itself*, not only to 1:
// - sin^2 > 1/2 (where the peak of small-alpha lobes lies): ln(1 - (n.h)^2) by
//   ln(1 - y) = -2 atanh(y / (2 - y)) and the atanh series to w^17 (w <= 1/3: truncation
//   < 2e-9 relative). Forming sin^2 = |n x h|^2 ~ 1 there and taking its log would carry an
//   absolute ~6e-8 rounding into ln(sin^2), i.e. 6e-8 / (2 alpha) relative error in D: 12 % at
//   alpha = 2.4e-7 (docs/validation.md, before/after).
// - sin^2 <= 1/2: log(|n x h|^2) (1 - (n.h)^2 would cancel near n.h = 1).
// The error in D is then ~|ln D| ulps from exp's argument, bounded wherever D is not
// negligible. pow(0, y) = 0 becomes exp(log(0)) = exp(-inf) = 0. No fp16 floor (Filament's
// max(sin2h, 2^-7) is a fp16 guard; it changes D near n.h = 1).
float mb_d_charlie(Geometry g, float alpha) {
    // dot(n, h), not g.NoH: makeGeometry clamps NoH at 0, and a half vector below the
    // tangent plane (area-light representative directions) has sin^2 = 1 - (n.h)^2 < 1, as
    // the |n x h| of the reference gives.
    float NoH = dot(g.n, g.h);
    float c2 = NoH * NoH;
    float lnSin2;
    if (c2 < 0.5) {
        float w = c2 / (2.0 - c2), w2 = w * w;
        float s = 1.0 / 17.0;
        s = s * w2 + 1.0 / 15.0;
        s = s * w2 + 1.0 / 13.0;
        s = s * w2 + 1.0 / 11.0;
        s = s * w2 + 1.0 / 9.0;
        s = s * w2 + 1.0 / 7.0;
        s = s * w2 + 1.0 / 5.0;
        s = s * w2 + 1.0 / 3.0;
        s = s * w2 + 1.0;
        lnSin2 = -2.0 * w * s;
    } else {
        vec3 nxh = cross(g.n, g.h);
        lnSin2 = log(dot(nxh, nxh));
    }
    float invAlpha = 1.0 / alpha;
    return (2.0 + invAlpha) * exp(0.5 * invAlpha * lnSin2) * (0.5 / MB_PI);
}
