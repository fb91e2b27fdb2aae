// Reference for tube_ltc_sheen_cv: norm times D_M over its silhouette polygon plus the
// residual's fan quadrature, with the sheen lobe (common/ltc_reference.hpp,
// polygonSpecularWithResidual with LobeKind::Charlie). Ground truth: the sheen lobe Charlie D x
// Ashikhmin V x n.l integrated adaptively over the capsule's silhouette with 256-gon caps above the horizon (lobeOverPolygon).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double tubeLtcSheenCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22, Vec3 L0,
                      Vec3 L1, double radius) {
  return ltc::polygonSpecularWithResidual(ltc::minvOf(m00, m02, m20, m22), norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::tubePolygon(L0, L1, radius, g.n), ltc::kResidualLevels,
                                          ltc::LobeKind::Charlie);
}

double tubeSheenTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 L0, Vec3 L1,
                      double radius) {
  return ltc::lobeOverPolygon(g.n, g.v, alpha, ltc::tubePolygon(L0, L1, radius, g.n, 256), ltc::LobeKind::Charlie);
}

}  // namespace

MB_REFERENCE("tube_ltc_sheen_cv", tubeLtcSheenCv);
MB_GROUND_TRUTH("tube_ltc_sheen_cv", tubeSheenTruth);

}  // namespace mb::ref
