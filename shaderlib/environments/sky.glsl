// The preview's sky with a sun (docs/environments.md; parameters in compiler/preview/
// environment_radiance.cpp, written before this file as constants kSun*, kZenith, kHorizon,
// kGlow, kGlowWidth, kGround, kHorizonBlend, kLimbDarkening). A simple analytic sky, not
// Preetham: a zenith-to-horizon gradient horizon + (zenith - horizon)(1 - (1 - y)^4), a
// forward-scattering halo around the sun glow exp((cos(gamma) - 1) / width), a uniform ground
// blended in below the horizon, and the sun's disc with a soft edge and the linear limb
// darkening law I(mu) = 1 - u (1 - mu), mu = cos of the angle at the sun's surface.
//
// The sun is a separate function: the prefilter kernel samples its cone directly (a 4000:1
// peak over 1e-3 sr defeats sampling by the GGX lobe alone; docs/environments.md).
vec3 mb_environment_smooth(vec3 d) {
    float t = 1.0 - clamp(d.y, 0.0, 1.0);
    float t2 = t * t;
    vec3 sky = kHorizon + (kZenith - kHorizon) * (1.0 - t2 * t2);
    vec3 glow = kGlow * exp((dot(d, kSunDirection) - 1.0) / kGlowWidth);
    return mix(kGround, sky + glow, smoothstep(-kHorizonBlend, 0.0, d.y));
}

// Zero outside the cone of half-angle kSunRadius + kSunEdge around kSunDirection.
vec3 mb_environment_sun(vec3 d) {
    // The angle to the sun's centre from the chord, which stays accurate near 0 where
    // acos(dot) loses half its digits.
    float gamma = 2.0 * asin(min(0.5 * length(d - kSunDirection), 1.0));
    float disc = 1.0 - smoothstep(kSunRadius - kSunEdge, kSunRadius + kSunEdge, gamma);
    if (disc <= 0.0) {
        return vec3(0.0);
    }
    float r = min(gamma / kSunRadius, 1.0);
    float mu = sqrt(1.0 - r * r);
    return kSun * (disc * (1.0 - kLimbDarkening * (1.0 - mu)));
}

vec3 mb_environment_radiance(vec3 d) {
    return mb_environment_smooth(d) + mb_environment_sun(d);
}
