// Radiance SH9 of a cube (docs/environments.md "SH9"): L_lm = sum over the texels of level 0
// of L(texel) Y_lm(d_texel) dOmega_texel, in double, with each texel's exact solid angle
// (environment_cube.hpp). The basis and order are those of the sh9_irradiance brick's
// reference (Ramamoorthi & Hanrahan 2001): L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 with
// Y1-1 ~ y, Y10 ~ z, Y11 ~ x.
#pragma once
#include <array>

#include "preview/environment.hpp"

namespace mb::preview {

// The nine real SH basis functions at unit direction d, in the order above.
std::array<double, 9> sh9Basis(const std::array<double, 3>& d);

// Projects `level` (any level; the preview uses level 0) into out[9][3].
void projectSh9(const CubeLevel& level, double out[9][3]);

}  // namespace mb::preview
