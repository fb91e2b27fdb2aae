// Reference for bent_normal_farcry4: McAuley 2015 ("Rendering the World of Far Cry 4"), the
// normal bent towards the view vector's part orthogonal to the anisotropy direction d:
//   N_a = (d x v) x d = v - d (d.v)   (for a unit d orthogonal to n),
//   bent = normalize((1 - k) n + k N_a),  k = |anisotropy| saturate(5 perceptualRoughness),
// with d = b for anisotropy >= 0 and t otherwise, in the Gram-Schmidt frame of (n, t).
#include <cmath>

#include "common/aniso_reference.hpp"

namespace mb::ref {

static Vec3 bentNormalFarCry4(Geometry g, Vec3 tangent, double anisotropy, double perceptualRoughness) {
  AnisoFrame f = anisoFrame(g.n, tangent);
  Vec3 d = anisotropy >= 0.0 ? f.b : f.t;
  Vec3 anisotropicNormal = g.v - d * dot(d, g.v);
  double k = std::abs(anisotropy) * clamp01(5.0 * perceptualRoughness);
  return normalize(g.n * (1.0 - k) + anisotropicNormal * k);
}

MB_REFERENCE("bent_normal_farcry4", bentNormalFarCry4);

}  // namespace mb::ref
