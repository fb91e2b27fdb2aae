// Schlick's Fresnel approximation (Schlick 1994, "An Inexpensive BRDF Model for Physically-
// based Rendering", eq. 15; seed 000 F_Schlick, seed 003 Function_F) with f90 exposed as in
// Lagarde & de Rousiers 2014 listing 1:
//   F = f0 + (f90 - f0) (1 - v.h)^5
// 1 - v.h is exact where it matters ((1 - v.h)^5 is negligible when v.h ~ 1); pow5 by
// multiplications (no pow() of a possibly negative base: v.h is clamped to [0, 1]).
vec3 mb_f_schlick(Geometry g, vec3 f0, float f90) {
    return f0 + (vec3(f90) - f0) * mb_pow5(1.0 - g.VoH);
}
