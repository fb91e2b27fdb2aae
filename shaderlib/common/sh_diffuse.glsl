// The Lambertian diffuse of the SH9 environment, shared by the models' environment light
// (models/standard_environment.glsl, models/cloth.glsl): diffuseColor * max(E(n), 0) / pi * ao,
// E the irradiance the bound sh_irradiance brick computes from the SH9 radiance (seed 003
// SampleSH9; Ramamoorthi & Hanrahan 2001). Only where an environment is shaded: the role, and
// its MB_SLOT_ macro, exist in no other permutation.

#ifndef MB_ENV_NONE
// The bound brick (the sh_irradiance slot's signature): a permutation includes its units
// before its bricks, so the brick is defined after this file.
vec3 MB_SLOT_sh_irradiance(vec3 n, vec3 sh0, vec3 sh1, vec3 sh2, vec3 sh3, vec3 sh4, vec3 sh5, vec3 sh6, vec3 sh7,
                           vec3 sh8);

vec3 mb_sh_diffuse(vec3 diffuseColor, vec3 n, Environment env, float ao) {
    // Clamped at 0, as Filament's Irradiance_SphericalHarmonics: a truncated SH expansion rings
    // below 0 away from a bright direction, and irradiance (hence radiance) is never negative
    // (validate fails a permutation on any negative output).
    vec3 irradiance = max(MB_SLOT_sh_irradiance(n, env.sh[0], env.sh[1], env.sh[2], env.sh[3], env.sh[4], env.sh[5],
                                                env.sh[6], env.sh[7], env.sh[8]),
                          0.0);
    return diffuseColor * irradiance * (ao * (1.0 / MB_PI));
}
#endif
