// EnergyNormalization with New_a2 (Unreal Engine 4, ShadingModels.ush; seed 002), sphere part:
//   New_a2 = a2 + 0.25 sin a (3 sqrt(a2) + sin a) / (v.h + 0.001),  energy = a2 / New_a2.
// sqrt(a2) is alpha itself. v.h is the shading geometry's (the source evaluates it after
// SphereMaxNoH has moved l; here it is the centre's).
float mb_norm_new_a2(Geometry g, float alpha, float sinAlpha) {
    float a2 = alpha * alpha;
    return a2 / (a2 + 0.25 * sinAlpha * (3.0 * alpha + sinAlpha) / (g.VoH + 0.001));
}
