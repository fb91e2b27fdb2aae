// Reference for disk_ltc_cv: norm times D_M over the ellipse's area-matched 8-gon plus the residual's fan
// quadrature (common/ltc_reference.hpp, polygonSpecularWithResidual). Ground truth: the GGX lobe
// D V (n.l) over the ellipse's 256-gon (the ellipse to ~1e-4 of its irradiance) above the horizon, by an adaptive fan
// (lobeIntegralAdaptive).
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double diskLtcCv(Geometry g, double alpha, double norm, double m00, double m02, double m20, double m22, Vec3 toCenter,
                 Vec3 halfX, Vec3 halfY) {
  return ltc::polygonSpecularWithResidual(ltc::minvOf(m00, m02, m20, m22), norm, alpha, ltc::viewFrame(g.n, g.v), g.v,
                                          ltc::diskPolygon(toCenter, halfX, halfY));
}

double diskLobeTruth(Geometry g, double alpha, double, double, double, double, double, Vec3 toCenter, Vec3 halfX,
                     Vec3 halfY) {
  return ltc::lobeOverPolygon(g.n, g.v, alpha, ltc::diskPolygon(toCenter, halfX, halfY, 256));
}

}  // namespace

MB_REFERENCE("disk_ltc_cv", diskLtcCv);
MB_GROUND_TRUTH("disk_ltc_cv", diskLobeTruth);

}  // namespace mb::ref
