// Reference for sphere_ltc_sheen_cv: norm times D_M over its cap's 8-gon plus the
// residual's fan quadrature, with the sheen lobe (common/ltc_reference.hpp,
// polygonSpecularWithResidual with LobeKind::Charlie). Ground truth: the sheen lobe Charlie D x
// Ashikhmin V x n.l integrated adaptively over the cap's area-matched 256-gon above the horizon (lobeOverPolygon).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double sphereLtcSheenCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22,
                        Vec3 toCenter, double radius) {
  return ltc::polygonSpecularWithResidual(ltc::minvOf(m00, m02, m20, m22), norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::spherePolygon(toCenter, radius, g.n), ltc::kResidualLevels,
                                          ltc::LobeKind::Charlie);
}

double sphereSheenTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 toCenter,
                        double radius) {
  return ltc::lobeOverPolygon(g.n, g.v, alpha, ltc::spherePolygon(toCenter, radius, g.n, 256), ltc::LobeKind::Charlie);
}

}  // namespace

MB_REFERENCE("sphere_ltc_sheen_cv", sphereLtcSheenCv);
MB_GROUND_TRUTH("sphere_ltc_sheen_cv", sphereSheenTruth);

}  // namespace mb::ref
