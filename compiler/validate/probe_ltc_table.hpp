// The LTC table a permutation's validation probe reads (rectangle and disk lights): the
// library's shipped table (ltc::kLibraryTableFile), for the kernel as the harness's table
// buffer (ltc::tableTexels) and for the reference as the fragment stage's blend in double.
#pragma once
#include <memory>
#include <vector>

#include "common/model_reference.hpp"
#include "library/shader_library.hpp"
#include "ltc/ltc_table.hpp"

namespace mb {

struct ProbeLtcTable {
  ltc::Table table;
  std::vector<float> texels;  // ltc::tableTexels(table): the kernel's mbTable
};

// The library's table, read once per library root in a process (thread-safe). A malformed or
// missing file throws DiagnosticError with its location (ltc::loadTable).
std::shared_ptr<const ProbeLtcTable> probeLtcTable(const ShaderLibrary& lib);

// What the shader's mb_fetch_ltc_matrix and mb_fetch_ltc_magnitude return at (n.v, roughness):
// the four entries around the point weighted as mb_ltc_texel weighs them
// (emit/ltc_table_lookup.hpp), in double. ModelEvalInput::fetchLtc is this.
ref::LtcTexel ltcTableTexel(const ltc::Table& table, double NoV, double perceptualRoughness);

}  // namespace mb
