// The LTC tables a permutation's validation probe reads (the area lights shaded by LTC): the
// library's shipped tables (ltc::kLibraryTableFile and kLibrarySheenTableFile), for the kernel as
// the harness's table buffer (ltc::tableTexels) and for the reference as the fragment stage's
// blend in double.
#pragma once
#include <memory>
#include <vector>

#include "common/model_reference.hpp"
#include "library/shader_library.hpp"
#include "ltc/ltc_table.hpp"

namespace mb {

struct ProbeLtcTable {
  ltc::Table table;           // the specular lobe's (GGX)
  ltc::Table sheen;           // the sheen's (Charlie)
  std::vector<float> texels;  // ltc::tableTexels(table, sheen): the kernel's mbTable, the fragment stage's texture

  // What the shader's hooks return for `lobe` (ltcTableTexel of its table): ModelEvalInput::fetchLtc.
  ref::LtcTexel texel(ref::LtcLobe lobe, double NoV, double perceptualRoughness) const;
};

// The library's tables, read once per library root in a process (thread-safe). A malformed or
// missing file throws DiagnosticError with its location (ltc::loadTable).
std::shared_ptr<const ProbeLtcTable> probeLtcTable(const ShaderLibrary& lib);

// What the shader's mb_fetch_ltc_matrix and mb_fetch_ltc_magnitude return at (n.v, roughness):
// the four entries around the point weighted as mb_ltc_texel weighs them
// (emit/ltc_table_lookup.hpp), in double.
ref::LtcTexel ltcTableTexel(const ltc::Table& table, double NoV, double perceptualRoughness);

}  // namespace mb
