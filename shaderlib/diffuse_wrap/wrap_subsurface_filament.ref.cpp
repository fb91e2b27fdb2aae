// Reference for wrap_subsurface_filament: Filament's cloth diffuse (sec. 4.12.2),
//   Fd * saturate((cos theta_l + w) / (1 + w)^2) * saturate(subsurfaceColor + cos theta_l),
// with the signed cosine; returns the factor that multiplies Fd (and replaces max(n.l, 0)).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 wrapSubsurfaceFilament(Geometry g, double w, Vec3 subsurfaceColor) {
  double cosTheta = dot(g.n, g.l);
  double wrapped = clamp01((cosTheta + w) / std::pow(1.0 + w, 2.0));
  Vec3 tint{clamp01(subsurfaceColor.x + cosTheta), clamp01(subsurfaceColor.y + cosTheta),
            clamp01(subsurfaceColor.z + cosTheta)};
  return tint * wrapped;
}

MB_REFERENCE("wrap_subsurface_filament", wrapSubsurfaceFilament);

}  // namespace mb::ref
