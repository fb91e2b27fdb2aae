// No multiple-scattering compensation: the single-scattering lobe as is (factor 1). The
// Cook-Torrance lobe then loses up to ~60% of its energy at alpha = 1 (Kulla & Conty 2017).
vec3 mb_energy_compensation_none(vec3 f0, float dfgY) {
    return vec3(1.0);
}
