// Fitting linearly transformed cosines to the GGX cosine lobe (Heitz, Dupuy, Hill & Neubelt
// 2016, section 4): per perceptual roughness and view angle, the matrix M whose distribution
// D_M (common/ltc_reference.hpp) is closest to D V (n.l) / norm, with D GGX (alpha = r^2) and V
// the exact height-correlated Smith visibility the standard model uses (Heitz 2014 eq. 99).
// The lobe's magnitude norm = Int D V (n.l) dl and its Schlick-weighted part
// Int D V (n.l) (1 - v.h)^5 dl come from the split-sum quadrature (common/ibl_reference.hpp):
// they are the DFG integrals, not fitted.
#pragma once
#include <cstdint>
#include <vector>

#include "common/ltc_reference.hpp"

namespace mb::ltc {

enum class LobeKind { Ggx, Charlie };
const char* lobeName(LobeKind k);  // "ggx", "charlie"

// How the table's axes map to the lobe (Heitz 2016's parametrization): row i is perceptual
// roughness r = i / (size - 1), alpha = max(r^2, minAlpha(lobe)); column j is u = j / (size - 1),
// n.v = max(1 - u^2, kMinNoV). Charlie's floor is the cloth model's roughness clamp
// (alpha >= 0.002025, Filament's): below it the sheen lobe is a sliver at the horizon whose
// fp32 evaluation the sheen bricks do not claim.
inline constexpr double kMinAlpha = 1e-4;
inline constexpr double kMinCharlieAlpha = 0.002025;
inline constexpr double kMinNoV = 1e-4;
double minAlpha(LobeKind k);
double tableRoughness(uint32_t i, uint32_t size);
double tableNoV(uint32_t j, uint32_t size);

struct FitSettings {
  LobeKind lobe = LobeKind::Ggx;
  uint32_t samples = 32;  // per side of the stratified grids the error is estimated on
  uint32_t maxIterations = 400;
};

// M = B S in the frame of the view (n = z, v in the x-z plane with v.x >= 0), with B the
// rotation taking z to the lobe's mean direction and S = [[a, 0, b], [0, c, 0], [0, 0, 1]].
struct LtcShape {
  double a = 1, b = 0, c = 1;
};

struct LtcEntry {
  double roughness = 0, NoV = 1;
  LtcShape shape;
  ref::ltc::Mat3 m{};     // M
  ref::ltc::Mat3 minv{};  // M^-1 scaled so that minv[1][1] = 1 (D_M does not depend on the scale)
  double norm = 0;        // Int D V (n.l) dl  (ggx: the DFG Int Gv; charlie: the cloth channel)
  double fresnel = 0;     // ggx: Int D V (n.l) (1 - v.h)^5 dl  (the DFG Int Gv Fc); charlie: 0
  double error = 0;       // the minimized cubic error (see ltc_fit.cpp)
  uint32_t iterations = 0;
};

// One entry, started from `start` (the fit walks each column from rough to smooth, starting
// each entry from its rougher neighbour).
LtcEntry fitEntry(double roughness, double NoV, const LtcShape& start, const FitSettings& settings);

// The fitter's error (ltc_fit.cpp) of a shape at one entry, and the shape a stored M^-1 stands
// for (M = B S recovered from M^-1 up to its scale): together they check a stored table.
double fitError(double roughness, double NoV, const LtcShape& shape, const FitSettings& settings);
LtcShape shapeOf(double roughness, double NoV, const ref::ltc::Mat3& minv, const FitSettings& settings);

// The whole table, row-major by roughness; columns are fitted on `threads` threads (0: all
// cores). The result does not depend on the thread count.
std::vector<LtcEntry> fitTable(uint32_t size, const FitSettings& settings, uint32_t threads = 0);

}  // namespace mb::ltc
