// A numeric CSV table with a header row (the input format of `matbricks eval`). Errors name
// file:line:column.
#pragma once
#include <string>
#include <vector>

#include "core/diagnostics.hpp"

namespace mb {

struct CsvTable {
  std::string file;
  std::vector<std::string> header;
  int headerLine = 0;
  std::vector<int> headerColumns;  // 1-based column of each header field
  std::vector<std::vector<double>> rows;
  std::vector<int> rowLines;  // source line of each row
};

// Reads a CSV of numbers. Blank lines and lines starting with '#' are skipped.
CsvTable loadCsv(const std::string& path);
CsvTable parseCsv(const std::string& text, const std::string& file);

// Reorders the columns to `expected`: every expected column must be present, and no other.
// Throws DiagnosticError naming the header's line and column.
std::vector<std::vector<double>> selectColumns(const CsvTable& table, const std::vector<std::string>& expected);

}  // namespace mb
