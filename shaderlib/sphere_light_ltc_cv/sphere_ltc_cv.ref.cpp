// Reference for sphere_ltc_cv: norm times D_M over the cap's 8-gon plus the residual's fan
// quadrature (common/ltc_reference.hpp, polygonSpecularWithResidual). Ground truth: the GGX
// lobe D V (n.l) integrated over the exact cap above the horizon (area_light_truth.hpp).
#include "common/area_light_truth.hpp"
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double sphereLtcCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22, Vec3 toCenter,
                   double radius) {
  const ltc::Mat3 minv = ltc::minvOf(m00, m02, m20, m22);
  return ltc::polygonSpecularWithResidual(minv, norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::spherePolygon(toCenter, radius, g.n));
}

double sphereLobeTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 toCenter, double radius) {
  double d = length(toCenter);
  double sinA = ltc::ballSinAlpha(d, radius);
  if (!(sinA > 0.0)) return 0.0;
  return arealights::sphereLobe(makeGeometry(g.n, g.v, toCenter / d), alpha, sinA, 32).specular;
}

}  // namespace

MB_REFERENCE("sphere_ltc_cv", sphereLtcCv);
MB_GROUND_TRUTH("sphere_ltc_cv", sphereLobeTruth);

}  // namespace mb::ref
