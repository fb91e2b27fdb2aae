// Exact F0 of the base layer under a clear coat of IOR 1.5 (Filament sec. 4.9.4: "iorToF0(
// f0ToIor(f0), 1.5)"): with n = (1 + s)/(1 - s), s = sqrt f0,
//   F0' = ((n - 1.5)/(n + 1.5))^2 = ((5 s - 1)/(5 - s))^2
// The second form (multiply through by 2 (1 - s)) has no division by 1 - s, so f0 = 1 gives
// 1 with no infinity; it is exact algebra, not an approximation.
vec3 mb_f0_clearcoat_exact(vec3 f0) {
    vec3 s = sqrt(f0);
    vec3 r = (5.0 * s - 1.0) / (5.0 - s);
    return r * r;
}
