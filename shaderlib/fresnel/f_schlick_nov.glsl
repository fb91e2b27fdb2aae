// Schlick's Fresnel at the view angle to the normal rather than to the half vector:
//   F = f0 + (f90 - f0) (1 - n.v)^5
// KHR_materials_clearcoat's fresnel_coat weighs the coat by Schlick at |n_c.v| (n_c the coat
// normal), ignoring the microfacet orientation so that the layering conserves energy with a
// single weight for base and coat. The glTF import binds it to clearcoat_fresnel.
vec3 mb_f_schlick_nov(Geometry g, vec3 f0, float f90) {
    return f0 + (vec3(f90) - f0) * mb_pow5(1.0 - g.NoV);
}
