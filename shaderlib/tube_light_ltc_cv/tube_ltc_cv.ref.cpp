// Reference for tube_ltc_cv: norm times D_M over the capsule's silhouette polygon plus the
// residual's fan quadrature (common/ltc_reference.hpp, polygonSpecularWithResidual). Ground
// truth: the GGX lobe D V (n.l) integrated over the exact capsule (area_light_truth.hpp).
#include "common/area_light_truth.hpp"
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double tubeLtcCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22, Vec3 L0,
                 Vec3 L1, double radius) {
  const ltc::Mat3 minv = ltc::minvOf(m00, m02, m20, m22);
  return ltc::polygonSpecularWithResidual(minv, norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::tubePolygon(L0, L1, radius, g.n));
}

double tubeLobeTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 L0, Vec3 L1,
                     double radius) {
  if (!(radius > 0.0)) return 0.0;
  return arealights::tubeLobe(makeGeometry(g.n, g.v, g.n), alpha, L0, L1, radius).specular;
}

}  // namespace

MB_REFERENCE("tube_ltc_cv", tubeLtcCv);
MB_GROUND_TRUTH("tube_ltc_cv", tubeLobeTruth);

}  // namespace mb::ref
