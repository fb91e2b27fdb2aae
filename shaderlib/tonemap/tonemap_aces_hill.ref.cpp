// Reference for tonemap_aces_hill: Hill 2016 (BakingLab ACES.hlsl), written row by row:
//   v_i = sum_j In[i][j] c_j,  f(v) = (v^2 + 0.0245786 v - 0.000090537) / (0.983729 v^2 + 0.4329510 v + 0.238081),
//   out_i = clamp(sum_j Out[i][j] f(v_j), 0, 1).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 rowTimes(const double m[3][3], const Vec3& c) {
  return {m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
          m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z};
}

static double rrtOdtFit(double v) {
  return (v * v + 0.0245786 * v - 0.000090537) / (0.983729 * v * v + 0.4329510 * v + 0.238081);
}

static Vec3 tonemapAcesHill(Vec3 color) {
  // sRGB => XYZ => D65_2_D60 => AP1 => RRT_SAT
  static const double in[3][3] = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  // ODT_SAT => XYZ => D60_2_D65 => sRGB
  static const double out[3][3] = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  Vec3 v = rowTimes(in, color);
  Vec3 r = rowTimes(out, {rrtOdtFit(v.x), rrtOdtFit(v.y), rrtOdtFit(v.z)});
  return {clamp01(r.x), clamp01(r.y), clamp01(r.z)};
}

MB_REFERENCE("tonemap_aces_hill", tonemapAcesHill);

}  // namespace mb::ref
