// Reference for rect_ltc_polygon: D_M over the rectangle's polygon by Lambert's edge sum after
// the horizon and support clips (common/ltc_reference.hpp, Heitz et al. 2016 eq. 11).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double rectLtcPolygon(Geometry g, double m00, double m02, double m20, double m22, Vec3 toCenter, Vec3 halfX,
                      Vec3 halfY) {
  return ltc::polygonIntegral(ltc::minvOf(m00, m02, m20, m22), ltc::viewFrame(g.n, g.v),
                              ltc::rectPolygon(toCenter, halfX, halfY));
}

}  // namespace

MB_REFERENCE("rect_ltc_polygon", rectLtcPolygon);

}  // namespace mb::ref
