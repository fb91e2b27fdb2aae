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
  const ltc::ViewFrame fr = ltc::viewFrame(g.n, g.v);
  std::vector<Vec3> local;
  for (const Vec3& w : ltc::rectPolygon(toCenter, halfX, halfY)) local.push_back(fr.toLocal(w));
  local = ltc::clipToHalfSpace(local, Vec3{0, 0, 1});
  // To 1e-7 of the light's irradiance (the lobe's integral is at most a few times it).
  return ltc::lobeIntegralAdaptive(local, fr.toLocal(g.v), alpha, 1e-7 * kPi * ltc::clampedCosinePolygon(local));
}

}  // namespace

MB_REFERENCE("rect_ltc_cv", rectLtcCv);
MB_GROUND_TRUTH("rect_ltc_cv", rectLobeTruth);

}  // namespace mb::ref
