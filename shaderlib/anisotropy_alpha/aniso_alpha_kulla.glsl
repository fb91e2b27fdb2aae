// Anisotropic alphas, Kulla & Conty 2017 ("Revisiting Physically Based Shading at
// Imageworks", p. 20), as Filament and seed 000: at = alpha (1 + a), ab = alpha (1 - a).
// a > 0 stretches the highlight along t, a < 0 along b; a = 0 gives at = ab = alpha.
vec3 mb_aniso_alpha_kulla(float alpha, float anisotropy) {
    return vec3(alpha * (1.0 + anisotropy), alpha * (1.0 - anisotropy), 0.0);
}
