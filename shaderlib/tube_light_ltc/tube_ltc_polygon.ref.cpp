// Reference for tube_ltc_polygon: the capsule's silhouette polygon (common/ltc_reference.hpp,
// tubePolygon), D_M integrated by Lambert's edge sum after the horizon and support clips
// (Heitz et al. 2016 eq. 11). Its error against the GGX lobe over the exact capsule is
// measured by mb_bench_area_lights (docs/models/lights.md).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double tubeLtcPolygon(Geometry g, double m00, double m02, double m20, double m22, Vec3 L0, Vec3 L1, double radius) {
  const ltc::Mat3 minv = ltc::minvOf(m00, m02, m20, m22);
  return ltc::polygonIntegral(minv, ltc::viewFrame(g.n, g.v), ltc::tubePolygon(L0, L1, radius, g.n));
}

}  // namespace

MB_REFERENCE("tube_ltc_polygon", tubeLtcPolygon);

}  // namespace mb::ref
