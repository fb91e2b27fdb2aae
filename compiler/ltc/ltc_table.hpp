// The fitted LTC table as a library asset (shaderlib/ltc/ggx.json, docs/models/lights.md
// "LTC tables"): per entry the inverse matrix M^-1 (its four free elements, with
// minv[1][1] = 1 and the other elements 0), the lobe's magnitude and its Fresnel part, each
// rounded to fp32 so that the GPU's texture and the double reference read the same numbers.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "ltc/ltc_fit.hpp"

namespace mb::ltc {

// The tables the library ships, relative to its root (the fragment stage's LTC texture): the
// specular lobe's and the sheen's.
inline constexpr const char* kLibraryTableFile = "ltc/ggx.json";
inline constexpr const char* kLibrarySheenTableFile = "ltc/charlie.json";

struct TableEntry {
  float m00 = 1, m02 = 0, m20 = 0, m22 = 1;  // M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
  float norm = 0, fresnel = 0;

  ref::ltc::Mat3 minv() const;
};

struct Table {
  uint32_t size = 0;
  FitSettings settings;
  std::vector<TableEntry> entries;  // row i (roughness) major, column j (view)

  const TableEntry& at(uint32_t i, uint32_t j) const { return entries[size_t{i} * size + j]; }
};

// The table read as a GPU reads a texture of it with bilinear filtering and clamp-to-edge,
// in double: the four entries around (roughness, u = sqrt(1 - n.v)) on the grid i / (size - 1),
// weighted linearly (the table's axes, ltc_fit.hpp).
struct TableSample {
  ref::ltc::Mat3 minv{};
  double norm = 0, fresnel = 0;
};
TableSample sampleBilinear(const Table& t, double perceptualRoughness, double NoV);

// The tables as the GPU reads them (the fragment stage's texture, a probe's table buffer): 4 size
// by size RGBA entries, row i (roughness) holding the specular table's size matrix entries
// (m00, m02, m20, m22), then its size magnitude entries (norm, fresnel, 0, 0), then the sheen
// table's likewise; row after row. The two tables must have the same size.
std::vector<float> tableTexels(const Table& specular, const Table& sheen);

TableEntry toTableEntry(const LtcEntry& e);
Table makeTable(uint32_t size, const FitSettings& settings, const std::vector<LtcEntry>& fitted);

// The file's text (JSON; `command` records how it was made).
std::string encodeTable(const Table& t, const std::string& command);
// Reads a table; a malformed file throws DiagnosticError with its file:line:column.
Table loadTable(const std::string& path);

}  // namespace mb::ltc
