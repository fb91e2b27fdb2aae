#include "load/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string_view>

#include "core/input_file.hpp"

namespace mb {

std::string quotedExcerpt(const std::string& text, size_t maxChars) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= maxChars) return out + "...";
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

// A named namespace, not an anonymous one: CsvReader::State (declared in the header) holds a
// LineSource and Fields, and GCC warns (-Wsubobject-linkage) when a type with external linkage
// has members of internal-linkage types outside the main file, as in a unity build.
namespace csv_detail {

std::string_view trim(std::string_view s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string_view::npos ? std::string_view() : s.substr(a, b - a + 1);
}

// One field of a line: its trimmed text and 1-based column.
struct Field {
  std::string_view text;
  int column;
};

// Splits a line on commas into `out` (reused between lines: no allocation per row).
void splitFields(std::string_view line, std::vector<Field>& out) {
  out.clear();
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    const std::string_view raw =
        line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    const size_t lead = raw.find_first_not_of(" \t");
    out.push_back({trim(raw), static_cast<int>(start + (lead == std::string_view::npos ? 0 : lead)) + 1});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

// The lines of a file, read in blocks, or of text in memory.
class LineSource {
 public:
  LineSource(std::optional<InputFile> file, std::string text) : file_(std::move(file)), buf_(std::move(text)) {}

  // The next line without its '\n'; nothing at the end. Throws `tooLong` (after filling it)
  // for a line over kMaxCsvLineBytes, and a read error as a diagnostic of the file.
  std::optional<std::string_view> next(const std::string& fileName) {
    for (;;) {
      const size_t nl = buf_.find('\n', scanFrom_);
      if (nl != std::string::npos) {
        std::string_view line(buf_.data() + pos_, nl - pos_);
        pos_ = scanFrom_ = nl + 1;
        return checked(line, fileName);
      }
      scanFrom_ = buf_.size();
      if (buf_.size() - pos_ > kMaxCsvLineBytes) return checked(std::string_view(buf_).substr(pos_), fileName);
      if (!file_ || !refill(fileName)) {
        if (pos_ >= buf_.size()) return std::nullopt;
        std::string_view line(buf_.data() + pos_, buf_.size() - pos_);
        pos_ = scanFrom_ = buf_.size();
        return checked(line, fileName);
      }
    }
  }

  bool lineTooLong = false;

 private:
  std::optional<std::string_view> checked(std::string_view line, const std::string&) {
    if (line.size() > kMaxCsvLineBytes) lineTooLong = true;
    return line;
  }
  // Appends the next block of the file; false at its end.
  bool refill(const std::string& fileName) {
    buf_.erase(0, pos_);
    scanFrom_ -= pos_;
    pos_ = 0;
    const size_t have = buf_.size();
    buf_.resize(have + kBlock);
    InputFileError error;
    const long got = file_->read(buf_.data() + have, kBlock, error);
    if (got < 0) throw DiagnosticError({{Severity::Error, error.code, {fileName, 0, 0}, error.message}});
    buf_.resize(have + static_cast<size_t>(got));
    if (got == 0) file_.reset();
    return got > 0;
  }

  static constexpr size_t kBlock = 1 << 16;
  std::optional<InputFile> file_;
  std::string buf_;
  size_t pos_ = 0, scanFrom_ = 0;
};

}  // namespace csv_detail

struct CsvReader::State {
  State(std::optional<InputFile> file, std::string text, const std::string& name)
      : lines(std::move(file), std::move(text)) {
    header.file = name;
  }
  csv_detail::LineSource lines;
  CsvHeader header;
  std::vector<Diagnostic> errors;
  std::vector<csv_detail::Field> fields;
  int lineNo = 0;
  bool stopped = false;

  void error(const std::string& code, int line, int column, const std::string& message) {
    errors.push_back({Severity::Error, code, {header.file, line, column}, message, ""});
    if (errors.size() >= kMaxCsvErrors) {
      errors.back().message += " (stopped after " + std::to_string(kMaxCsvErrors) + " errors)";
      stopped = true;
    }
  }

  // The next line that is neither blank nor a comment, split into `fields`.
  bool nextContentLine() {
    while (!stopped) {
      const auto line = lines.next(header.file);
      if (!line) return false;
      ++lineNo;
      if (lines.lineTooLong) {
        error("E-CSV-LINE-TOO-LONG", lineNo, 1,
              "a line of more than " + std::to_string(kMaxCsvLineBytes) + " bytes, starting '" +
                  quotedExcerpt(std::string(line->substr(0, 64))) + "': not a row of numbers");
        stopped = true;
        return false;
      }
      const std::string_view content = csv_detail::trim(*line);
      if (content.empty() || content[0] == '#') continue;
      splitFields(*line, fields);
      return true;
    }
    return false;
  }

  void readHeader() {
    if (nextContentLine()) {
      for (const auto& f : fields) {
        header.names.emplace_back(f.text);
        header.columns.push_back(f.column);
      }
      header.line = lineNo;
    } else if (errors.empty()) {
      error("E-CSV-EMPTY", 1, 1, "expected a header row naming the inputs");
    }
    if (!errors.empty()) throw DiagnosticError(errors);
  }

  // The value of one field, or an error at its column.
  bool number(const csv_detail::Field& f, double& v) {
    const char* end = f.text.data() + f.text.size();
    const auto res = std::from_chars(f.text.data(), end, v);
    if (f.text.empty() || res.ec != std::errc() || res.ptr != end) {
      error("E-CSV-NUMBER", lineNo, f.column, "expected a number, found '" + quotedExcerpt(std::string(f.text)) + "'");
      return false;
    }
    if (!std::isfinite(v)) {
      error(
          "E-CSV-NUMBER", lineNo, f.column,
          "expected a finite number, found '" + quotedExcerpt(std::string(f.text)) + "' (NaN and Inf are not inputs)");
      return false;
    }
    if (std::abs(v) > std::numeric_limits<float>::max()) {
      error("E-CSV-NUMBER", lineNo, f.column,
            "'" + quotedExcerpt(std::string(f.text)) + "' is beyond the range of a 32-bit float (the inputs are fp32)");
      return false;
    }
    return true;
  }
};

CsvReader::CsvReader(std::unique_ptr<State> state) : s_(std::move(state)) { s_->readHeader(); }
CsvReader::CsvReader(CsvReader&&) noexcept = default;
CsvReader& CsvReader::operator=(CsvReader&&) noexcept = default;
CsvReader::~CsvReader() = default;

CsvReader CsvReader::open(const std::string& path) {
  InputFileError error;
  std::optional<InputFile> file = InputFile::open(path, input_kind::kCsv, error);
  if (!file) throw DiagnosticError({{Severity::Error, error.code, {path, 0, 0}, error.message}});
  return CsvReader(std::make_unique<State>(std::move(file), std::string(), path));
}

CsvReader CsvReader::over(std::string text, const std::string& file) {
  return CsvReader(std::make_unique<State>(std::nullopt, std::move(text), file));
}

const CsvHeader& CsvReader::header() const { return s_->header; }
const std::vector<Diagnostic>& CsvReader::errors() const { return s_->errors; }

void CsvReader::throwIfErrors() const {
  if (!s_->errors.empty()) throw DiagnosticError(s_->errors);
}

bool CsvReader::next(std::vector<double>& row, int& line) {
  State& s = *s_;
  while (s.nextContentLine()) {
    if (s.fields.size() != s.header.names.size()) {
      s.error("E-CSV-SHAPE", s.lineNo, 1,
              "row has " + std::to_string(s.fields.size()) + " fields, expected " +
                  std::to_string(s.header.names.size()) + " (one per header column)");
      continue;
    }
    row.resize(s.fields.size());
    bool ok = true;
    for (size_t k = 0; k < s.fields.size() && !s.stopped; ++k) ok = s.number(s.fields[k], row[k]) && ok;
    if (!ok) continue;
    line = s.lineNo;
    return true;
  }
  return false;
}

std::vector<size_t> columnOrder(const CsvHeader& header, const std::vector<std::string>& expected) {
  std::vector<Diagnostic> errors;
  std::vector<long> index(expected.size(), -1);
  for (size_t c = 0; c < header.names.size(); ++c) {
    auto it = std::find(expected.begin(), expected.end(), header.names[c]);
    if (it == expected.end()) {
      errors.push_back({Severity::Error,
                        "E-CSV-COLUMN",
                        {header.file, header.line, header.columns[c]},
                        "unknown column '" + quotedExcerpt(header.names[c]) + "'",
                        didYouMean(header.names[c], expected)});
    } else {
      index[static_cast<size_t>(it - expected.begin())] = static_cast<long>(c);
    }
  }
  std::string missing;
  for (size_t k = 0; k < expected.size(); ++k)
    if (index[k] < 0) missing += (missing.empty() ? "" : ", ") + expected[k];
  if (!missing.empty())
    errors.push_back(
        {Severity::Error, "E-CSV-COLUMN", {header.file, header.line, 1}, "missing column(s): " + missing, ""});
  if (!errors.empty()) {
    std::string all;
    for (size_t k = 0; k < expected.size(); ++k) all += (k ? "," : "") + expected[k];
    for (auto& e : errors) e.message += "; expected header: " + all;
    throw DiagnosticError(errors);
  }
  return std::vector<size_t>(index.begin(), index.end());
}

CsvTable parseCsv(const std::string& text, const std::string& file) {
  CsvReader reader = CsvReader::over(text, file);
  CsvTable t;
  t.header = reader.header();
  std::vector<double> row;
  int line = 0;
  while (reader.next(row, line)) {
    t.rows.push_back(row);
    t.rowLines.push_back(line);
  }
  reader.throwIfErrors();
  return t;
}

std::vector<std::vector<double>> selectColumns(const CsvTable& table, const std::vector<std::string>& expected) {
  const std::vector<size_t> index = columnOrder(table.header, expected);
  std::vector<std::vector<double>> out;
  for (const auto& row : table.rows) {
    std::vector<double> r;
    for (size_t i : index) r.push_back(row[i]);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mb
