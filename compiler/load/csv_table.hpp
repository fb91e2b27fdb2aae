// A numeric CSV table with a header row (the input format of `matbricks eval`). Errors name
// file:line:column and quote at most a short, printable excerpt of what they found. A file is
// read row by row (CsvReader) in constant memory, however many rows it has.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"

namespace mb {

// Errors collected from one table before stopping (a binary file would otherwise give one per
// line).
inline constexpr size_t kMaxCsvErrors = 20;
// A line longer than this is not a row of numbers: E-CSV-LINE-TOO-LONG, and reading stops.
inline constexpr size_t kMaxCsvLineBytes = 1 << 20;

struct CsvHeader {
  std::string file;
  std::vector<std::string> names;
  int line = 0;
  std::vector<int> columns;  // 1-based column of each name
};

// Reads a CSV of numbers row by row. Blank lines and lines starting with '#' are skipped; the
// first other line is the header. Every value must be a finite number within the range of a
// 32-bit float (eval's inputs are fp32).
class CsvReader {
 public:
  // Opens `path` (core/input_file.hpp: a regular file; a FIFO or device is refused at once)
  // and reads up to its header. Throws DiagnosticError for a file that cannot be read and for
  // a table without a header (E-CSV-EMPTY).
  static CsvReader open(const std::string& path);
  // The same over text already in memory (`file` names it in diagnostics).
  static CsvReader over(std::string text, const std::string& file);
  CsvReader(CsvReader&&) noexcept;
  CsvReader& operator=(CsvReader&&) noexcept;
  ~CsvReader();

  const CsvHeader& header() const;
  // The next well-formed row (one value per header name) and its line; false at the end. A
  // malformed row is skipped and its error collected; after kMaxCsvErrors, or a line over
  // kMaxCsvLineBytes, reading stops.
  bool next(std::vector<double>& row, int& line);
  const std::vector<Diagnostic>& errors() const;
  // Throws DiagnosticError with the errors collected so far, if any.
  void throwIfErrors() const;

 private:
  struct State;
  explicit CsvReader(std::unique_ptr<State> state);
  std::unique_ptr<State> s_;
};

// For each of `expected`, the index of its column in `header`: every expected column must be
// present, and no other. Throws DiagnosticError (E-CSV-COLUMN) naming the header's line and
// column.
std::vector<size_t> columnOrder(const CsvHeader& header, const std::vector<std::string>& expected);

// A whole table in memory (for small tables: tests, fuzzing).
struct CsvTable {
  CsvHeader header;
  std::vector<std::vector<double>> rows;
  std::vector<int> rowLines;  // source line of each row
};
CsvTable parseCsv(const std::string& text, const std::string& file);
// The rows with their columns in the order of `expected` (columnOrder).
std::vector<std::vector<double>> selectColumns(const CsvTable& table, const std::vector<std::string>& expected);

// At most `maxChars` of `text`, printable ASCII kept, other bytes as \xNN, "..." when cut:
// what a diagnostic may quote of a field of unknown content.
std::string quotedExcerpt(const std::string& text, size_t maxChars = 40);

}  // namespace mb
