// The LTC tables' lookup (docs/models/lights.md "LTC tables"), one text for the two shaders
// that read them: the fragment stage (a texture at kFragmentLtcBinding) and a permutation's
// validation probe (the harness's table buffer at kKernelTableBinding). Both define the hooks
// lights.glsl declares, mb_fetch_ltc_matrix and mb_fetch_ltc_magnitude (the specular table) and
// mb_fetch_ltc_sheen_matrix and mb_fetch_ltc_sheen_magnitude (the sheen's), by the same
// four-entry blend in fp32 arithmetic, so what validate certifies is what the fragment stage
// computes from the same numbers.
#pragma once
#include <string>
#include <vector>

#include "emit/precision.hpp"

namespace mb {

// Each table's side: 64 roughness rows by 64 view columns. A row of the texture is the specular
// table's 64 matrix entries, then its 64 magnitude entries, then the sheen table's 64 and 64
// (RGBA; ltc::tableTexels): kLtcTextureWidth texels.
inline constexpr int kLtcTableSize = 64;
inline constexpr int kLtcTextureWidth = 4 * kLtcTableSize;

// The lookup's GLSL, final text at precision `p` (its blend stays fp32; the hooks take and
// return the shading precision). `entry` is the GLSL of the table's RGBA entry at ivec2 `c`
// (column, row), with "@" standing for `c`: "texelFetch(mbLtcTable, @, 0)" in the fragment
// stage.
std::vector<std::string> ltcTableLookup(const std::string& entry, ShaderPrecision p);

// The validation probe's table hooks: the harness's table buffer (its floats are
// ltc::tableTexels, row after row), its entry mb_ltc_table_entry, and ltcTableLookup over it.
std::vector<std::string> ltcTableBufferHooks(ShaderPrecision p);

}  // namespace mb
