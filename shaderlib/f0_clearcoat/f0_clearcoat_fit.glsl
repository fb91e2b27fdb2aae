// F0 of the base layer seen through a clear coat of IOR 1.5: Filament's polynomial fit
// (Filament "Physically Based Rendering in Filament", sec. 4.9.4, f0ClearCoatToSurface;
// seed 000 F0ClearCoatToSurface):
//   F0' = saturate(f0 (f0 (0.941892 - 0.263008 f0) + 0.346479) - 0.0285998)
// Horner form; the result crosses 0 near f0 = 0.08 (the base matches the coat's IOR there),
// where the error is absolute.
vec3 mb_f0_clearcoat_fit(vec3 f0) {
    return clamp(f0 * (f0 * (0.941892 - 0.263008 * f0) + 0.346479) - 0.0285998, 0.0, 1.0);
}
