// Reference for rect_ltc_cv: norm times D_M over the rectangle's polygon plus the residual's fan
// quadrature (common/ltc_reference.hpp, polygonSpecularWithResidual). Ground truth: the GGX lobe
// D V (n.l) over the rectangle above the horizon, by an adaptive fan
// (lobeIntegralAdaptive).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double rectLtcCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22, Vec3 toCenter,
                 Vec3 halfX, Vec3 halfY) {
  return ltc::polygonSpecularWithResidual(ltc::minvOf(m00, m02, m20, m22), norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::rectPolygon(toCenter, halfX, halfY));
}

double rectLobeTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 toCenter, Vec3 halfX,
                     Vec3 halfY) {
  return ltc::lobeOverPolygon(g.n, g.v, alpha, ltc::rectPolygon(toCenter, halfX, halfY));
}

}  // namespace

MB_REFERENCE("rect_ltc_cv", rectLtcCv);
MB_GROUND_TRUTH("rect_ltc_cv", rectLobeTruth);

}  // namespace mb::ref
