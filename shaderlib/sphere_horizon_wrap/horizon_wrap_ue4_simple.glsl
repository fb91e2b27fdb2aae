// SphereHorizonCosWrap, the cheap alternative branch (Unreal Engine 4, CapsuleLight.ush;
// seed 002): saturate((n.l + sin^2 a) / (1 + sin^2 a)), a wrap-lighting curve in sin^2 a.
float mb_horizon_wrap_ue4_simple(Geometry g, float sinAlpha) {
    float s2 = sinAlpha * sinAlpha;
    return clamp((dot(g.n, g.l) + s2) / (1.0 + s2), 0.0, 1.0);
}
