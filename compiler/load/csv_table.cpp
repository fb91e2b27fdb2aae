#include "load/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

namespace mb {
namespace {

std::string trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// Splits a line on commas, recording each field's 1-based column.
std::vector<std::pair<std::string, int>> splitFields(const std::string& line) {
  std::vector<std::pair<std::string, int>> out;
  size_t start = 0;
  while (true) {
    size_t comma = line.find(',', start);
    std::string raw = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    size_t lead = raw.find_first_not_of(" \t");
    out.emplace_back(trim(raw), static_cast<int>(start + (lead == std::string::npos ? 0 : lead)) + 1);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

CsvTable parseCsv(const std::string& text, const std::string& file) {
  CsvTable t;
  t.file = file;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  std::vector<Diagnostic> errors;
  while (std::getline(in, line)) {
    ++lineNo;
    std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    auto fields = splitFields(line);
    if (t.header.empty()) {
      for (auto& [f, col] : fields) {
        t.header.push_back(f);
        t.headerColumns.push_back(col);
      }
      t.headerLine = lineNo;
      continue;
    }
    if (fields.size() != t.header.size()) {
      errors.push_back({Severity::Error,
                        "E-CSV-SHAPE",
                        {file, lineNo, 1},
                        "row has " + std::to_string(fields.size()) + " fields, expected " +
                            std::to_string(t.header.size()) + " (one per header column)",
                        ""});
      continue;
    }
    std::vector<double> row;
    for (auto& [f, col] : fields) {
      double v = 0;
      auto res = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || res.ec != std::errc() || res.ptr != f.data() + f.size()) {
        errors.push_back(
            {Severity::Error, "E-CSV-NUMBER", {file, lineNo, col}, "expected a number, found '" + f + "'", ""});
      }
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
    t.rowLines.push_back(lineNo);
  }
  if (t.header.empty())
    errors.push_back({Severity::Error, "E-CSV-EMPTY", {file, 1, 1}, "expected a header row naming the inputs", ""});
  if (!errors.empty()) throw DiagnosticError(errors);
  return t;
}

CsvTable loadCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw DiagnosticError(
        {{Severity::Error, "E-FILE-NOT-FOUND", {path, 0, 0}, "cannot open file: expected a readable CSV file", ""}});
  }
  std::stringstream ss;
  ss << in.rdbuf();
  return parseCsv(ss.str(), path);
}

std::vector<std::vector<double>> selectColumns(const CsvTable& table, const std::vector<std::string>& expected) {
  std::vector<Diagnostic> errors;
  // The header is the first non-comment line; find it again for column positions.
  std::vector<int> index(expected.size(), -1);
  for (size_t c = 0; c < table.header.size(); ++c) {
    auto it = std::find(expected.begin(), expected.end(), table.header[c]);
    if (it == expected.end()) {
      errors.push_back({Severity::Error,
                        "E-CSV-COLUMN",
                        {table.file, table.headerLine, table.headerColumns[c]},
                        "unknown column '" + table.header[c] + "'",
                        didYouMean(table.header[c], expected)});
    } else {
      index[it - expected.begin()] = static_cast<int>(c);
    }
  }
  std::string missing;
  for (size_t k = 0; k < expected.size(); ++k)
    if (index[k] < 0) missing += (missing.empty() ? "" : ", ") + expected[k];
  if (!missing.empty())
    errors.push_back(
        {Severity::Error, "E-CSV-COLUMN", {table.file, table.headerLine, 1}, "missing column(s): " + missing, ""});
  if (!errors.empty()) {
    std::string all;
    for (size_t k = 0; k < expected.size(); ++k) all += (k ? "," : "") + expected[k];
    for (auto& e : errors) e.message += "; expected header: " + all;
    throw DiagnosticError(errors);
  }
  std::vector<std::vector<double>> out;
  for (const auto& row : table.rows) {
    std::vector<double> r;
    for (int i : index) r.push_back(row[i]);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mb
