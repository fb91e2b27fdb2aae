// Reference for sphere_ltc_polygon: the sphere's cap as the area-matched 8-gon of its facing
// disk, D_M integrated by Lambert's edge sum after the horizon and support clips
// (common/ltc_reference.hpp, Heitz et al. 2016 eq. 11). Ground truth: D_M integrated over the
// exact cap by quadrature (lights::capIntegral), above the horizon, with no polygon.
#include "common/lights_reference.hpp"
#include "common/ltc_reference.hpp"

namespace mb::ref {
namespace {

double sphereLtcPolygon(Geometry g, double m00, double m02, double m20, double m22, Vec3 toCenter, double radius) {
  return ltc::polygonIntegral(ltc::minvOf(m00, m02, m20, m22), ltc::viewFrame(g.n, g.v),
                              ltc::spherePolygon(toCenter, radius, g.n));
}

double sphereLtcTruth(Geometry g, double m00, double m02, double m20, double m22, Vec3 toCenter, double radius) {
  double d = length(toCenter);
  Vec3 c = d > 0.0 ? toCenter / d : g.n;
  double sinA = ltc::ballSinAlpha(d, radius);
  if (!(sinA > 0.0)) return 0.0;
  ltc::Mat3 minv = ltc::minvOf(m00, m02, m20, m22);
  ltc::ViewFrame fr = ltc::viewFrame(g.n, g.v);
  Geometry gc = makeGeometry(g.n, g.v, c);
  // The quadrature grades its panels at the scale of alpha about the mirror ray. A table entry
  // of GGX roughness alpha is ~diag(1, 1, alpha) (scaled to minv[1][1] = 1) near normal
  // incidence, so m22 / m00 gives that scale.
  double alpha = std::clamp(m22 / std::max(m00, 1e-6), 0.002, 1.0);
  return lights::capIntegral(
      gc, alpha, sinA,
      [&](const Vec3& l) {
        Vec3 local = fr.toLocal(l);
        return local.z > 0.0 ? ltc::density(minv, local) : 0.0;
      },
      64);
}

}  // namespace

MB_REFERENCE("sphere_ltc_polygon", sphereLtcPolygon);
MB_GROUND_TRUTH("sphere_ltc_polygon", sphereLtcTruth);

}  // namespace mb::ref
