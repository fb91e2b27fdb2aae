// Reference for rect_ltc_sheen_cv: norm times D_M over the light's polygon plus the
// residual's fan quadrature, with the sheen lobe (common/ltc_reference.hpp,
// polygonSpecularWithResidual with LobeKind::Charlie). Ground truth: the sheen lobe Charlie D x
// Ashikhmin V x n.l integrated adaptively over the rectangle above the horizon (lobeOverPolygon).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double rectLtcSheenCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22,
                      Vec3 toCenter, Vec3 halfX, Vec3 halfY) {
  return ltc::polygonSpecularWithResidual(ltc::minvOf(m00, m02, m20, m22), norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::rectPolygon(toCenter, halfX, halfY), ltc::kResidualLevels,
                                          ltc::LobeKind::Charlie);
}

double rectSheenTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 toCenter, Vec3 halfX,
                      Vec3 halfY) {
  return ltc::lobeOverPolygon(g.n, g.v, alpha, ltc::rectPolygon(toCenter, halfX, halfY), ltc::LobeKind::Charlie);
}

}  // namespace

MB_REFERENCE("rect_ltc_sheen_cv", rectLtcSheenCv);
MB_GROUND_TRUTH("rect_ltc_sheen_cv", rectSheenTruth);

}  // namespace mb::ref
