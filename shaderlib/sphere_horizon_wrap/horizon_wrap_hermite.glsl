// SphereHorizonCosWrap, Hermite form (Unreal Engine 4, CapsuleLight.ush; seed 002): for a
// sphere light crossing the horizon, n.l is replaced by (sin a + n.l)^2 / (4 sin a) on
// [-sin a, sin a] (value and slope match 0 at -sin a and n.l at sin a).
// The source clamps n.l to -sin a and then divides by 4 sin a, which is 0/0 at sin a = 0 with
// n.l < 0 (a point light below the horizon); the range n.l <= -sin a is returned as 0 instead.
float mb_horizon_wrap_hermite(Geometry g, float sinAlpha) {
    float NoL = dot(g.n, g.l);
    if (NoL >= sinAlpha) return NoL;
    if (NoL <= -sinAlpha) return 0.0;
    float x = sinAlpha + NoL;
    return x * x / (4.0 * sinAlpha);
}
