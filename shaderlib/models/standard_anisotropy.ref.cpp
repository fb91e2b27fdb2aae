// Reference of the standard model's anisotropy (seed 000 "More PBR / Anisotropic Specular
// Material"; Filament "Physically Based Rendering in Filament" sec. 4.10), in double:
//   (at, ab) = max(anisotropy_alpha(alpha, a), alpha_min)
// (by default Kulla & Conty 2017's alpha (1 +- a), as Filament; glTF's mix(alpha, 1, a^2) and
// alpha; alpha_min = 0.045^2, Filament's fp32 MIN_ROUGHNESS),
// D and V from the anisotropic roles with the frame's tangent, and the bent normal of the
// image-based specular from the bent_normal_aniso role (McAuley 2015, Far Cry 4).
#include <algorithm>

#include "models/standard_reference.hpp"

namespace mb::ref::standard {

namespace {
constexpr double kMinAlpha = 0.045 * 0.045;
}

AnisotropyPixel anisotropyPrepare(const ModelEvalInput& in, double alpha) {
  AnisotropyPixel a;
  a.anisotropy = in.floatInput("anisotropy");
  const Vec3 alphas = in.vec3("anisotropy_alpha", Args() << alpha << a.anisotropy);
  a.at = std::max(alphas.x, kMinAlpha);
  a.ab = std::max(alphas.y, kMinAlpha);
  return a;
}

void anisotropyDV(const ModelEvalInput& in, const AnisotropyPixel& a, const Vec3& l, const Vec3& lD, double& D,
                  double& V) {
  const ShadingFrame& f = in.frame;
  D = in.scalar("specular_d_aniso", Args().geometry(f.n, f.v, lD) << f.t << a.at << a.ab);
  V = in.scalar("specular_v_aniso", Args().geometry(f.n, f.v, l) << f.t << a.at << a.ab);
}

Vec3 anisotropyIblNormal(const ModelEvalInput& in, const AnisotropyPixel& a, double perceptualRoughness) {
  const ShadingFrame& f = in.frame;
  const Vec3 r = f.n * (2.0 * dot(f.n, f.v)) - f.v;  // reflect(-v, n): the bricks read only n and v
  return in.vec3("bent_normal_aniso", Args().geometry(f.n, f.v, r) << f.t << a.anisotropy << perceptualRoughness);
}

}  // namespace mb::ref::standard
