// The LUT's file formats (docs/lut.md "Formats"): raw little-endian texels, KTX 2.0, CSV and a
// C header, each in fp32 or fp16. Encoding only; the CLI writes the bytes atomically.
#pragma once
#include <optional>
#include <string>

#include "lut/dfg_lut.hpp"

namespace mb::lut {

enum class OutputFormat { Raw, Ktx2, Csv, Header };
enum class Precision { Fp32, Fp16 };

// "raw", "ktx2", "csv", "header".
std::optional<OutputFormat> parseOutputFormat(const std::string& name);
// From the file extension: .bin/.raw, .ktx2, .csv, .h/.hpp; nullopt otherwise.
std::optional<OutputFormat> formatFromExtension(const std::string& path);
const char* formatName(OutputFormat f);

std::string encodeLut(const LutTable& table, OutputFormat format, Precision precision);

// The value a reader gets back from a file written at `precision` (fp16 rounds).
float storedValue(float value, Precision precision);

}  // namespace mb::lut
