// Multiple-scattering energy compensation (Filament "Physically Based Rendering in Filament",
// sec. 5.3.4.7, after Kulla & Conty 2017 and Turquin 2019; seed 000 CompensateDirectBRDF):
//   energyCompensation = 1 + f0 (1 / E - 1)
// with E = dfg.y = Int Gv, the single-scattering directional albedo at f0 = 1 (DESIGN.md DFG
// channel 1; seed 000 reads the same integral from its .r channel). Multiplies the specular
// lobe. E in (0, 1]: 1/E - 1 >= 0, no cancellation beyond the rounding of 1/E.
vec3 mb_energy_compensation_filament(vec3 f0, float dfgY) {
    return vec3(1.0) + f0 * (1.0 / dfgY - 1.0);
}
