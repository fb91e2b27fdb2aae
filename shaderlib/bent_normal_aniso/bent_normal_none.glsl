// No bending: the isotropic IBL lookup uses the shading normal itself (reflect(-v, n)).
// t, anisotropy and perceptualRoughness are unused; the slot's neutral choice.
vec3 mb_bent_normal_none(Geometry g, vec3 t, float anisotropy, float perceptualRoughness) {
    return g.n;
}
