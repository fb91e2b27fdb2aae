// ACES fitted (Hill 2016, BakingLab ACES.hlsl, after the ACES 1.0 RRT + sRGB ODT): linear
// sRGB -> AP1 with the RRT's saturation (ACESInputMat), a rational fit of RRT + ODT per
// channel, then the ODT's desaturation and AP1 -> linear sRGB (ACESOutputMat), saturated:
//   v = M_in c,  f(v) = (v (v + 0.0245786) - 0.000090537) / (v (0.983729 v + 0.4329510) + 0.238081),
//   out = saturate(M_out f(v))
// GLSL's mat3 takes columns: the published row-major matrices appear transposed below.
// Stability: the denominator has no real root (0.432951^2 < 4 * 0.983729 * 0.238081), so it is
// >= 0.19 for every v. The numerator crosses 0 at v ~ 0.0035 and M_out has negative
// coefficients; both only lose absolute accuracy of a few ulp of 1 (see slot.json).
vec3 mb_tonemap_aces_hill(vec3 color) {
    const mat3 inputMat = mat3(0.59719, 0.07600, 0.02840,
                               0.35458, 0.90834, 0.13383,
                               0.04823, 0.01566, 0.83777);
    const mat3 outputMat = mat3(1.60475, -0.10208, -0.00327,
                                -0.53108, 1.10813, -0.07276,
                                -0.07367, -0.00605, 1.07602);
    vec3 v = inputMat * color;
    vec3 fitted = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
    return clamp(outputMat * fitted, 0.0, 1.0);
}
