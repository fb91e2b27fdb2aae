// Specular environment BRDF from a DFG lookup in Filament's convention (DESIGN.md "DFG LUT
// convention"; Filament sec. 5.3.4.3, after Karis 2013's split sum):
//   E_spec = mix(dfg.xxx, dfg.yyy, f0) = (1 - f0) Int Gv Fc + f0 Int Gv
// with dfgX = Int Gv Fc (channel 0) and dfgY = Int Gv (channel 1), Fc = (1 - v.h)^5.
vec3 mb_dfg_lut_filament(vec3 f0, float dfgX, float dfgY) {
    return mix(vec3(dfgX), vec3(dfgY), f0);
}
