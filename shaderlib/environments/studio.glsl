// The preview's studio (docs/environments.md; parameters in compiler/preview/
// environment_radiance.cpp, written before this file as constants kBox*, kWall, kWallTop,
// kGround, kHorizonBlend, kBoxSoftness). Rectangular soft boxes over a dark backdrop and a dim
// floor. A box's mask is the product of two smoothsteps of the gnomonic coordinates
// x = d.u / d.c, y = d.v / d.c on the plane tangent at its centre c, so it is a rectangle on
// that plane (as a real rectangular light seen from the centre) with edges soft over
// +-kBoxSoftness.
vec3 mb_environment_smooth(vec3 d) {
    vec3 wall = mix(kWall, kWallTop, smoothstep(0.0, 1.0, d.y));
    vec3 radiance = mix(kGround, wall, smoothstep(-kHorizonBlend, 0.0, d.y));
    for (int k = 0; k < kBoxCount; ++k) {
        float c = dot(d, kBoxCentre[k]);
        if (c <= 0.0) {
            continue;
        }
        float x = abs(dot(d, kBoxU[k]) / c);
        float y = abs(dot(d, kBoxV[k]) / c);
        vec2 h = kBoxHalf[k];
        float mask = (1.0 - smoothstep(h.x - kBoxSoftness, h.x + kBoxSoftness, x)) *
                     (1.0 - smoothstep(h.y - kBoxSoftness, h.y + kBoxSoftness, y));
        radiance += mask * kBoxRadiance[k];
    }
    return radiance;
}

// No peak the GGX lobe cannot sample: everything is smooth.
vec3 mb_environment_radiance(vec3 d) {
    return mb_environment_smooth(d);
}
