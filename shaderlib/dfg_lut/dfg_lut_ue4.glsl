// Specular environment BRDF from a DFG lookup in UE4's scale/bias convention (Karis 2013,
// "Real Shading in Unreal Engine 4", split sum, IntegrateBRDF; seed 002):
//   E_spec = f0 * A + B,  A = Int (1 - Fc) Gv (dfgX), B = Int Fc Gv (dfgY)
vec3 mb_dfg_lut_ue4(vec3 f0, float dfgX, float dfgY) {
    return f0 * dfgX + vec3(dfgY);
}
