// The CSV of `matbricks eval` (load/csv_table.hpp): read row by row, every value a finite
// fp32 number, errors at file:line:column quoting at most a short printable excerpt.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "load/csv_table.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

std::vector<Diagnostic> errorsOf(const std::string& text) {
  try {
    parseCsv(text, "in.csv");
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

std::string where(const Diagnostic& d) {
  return d.code + "@" + std::to_string(d.where.line) + ":" + std::to_string(d.where.column);
}

}  // namespace

TEST_CASE("csv: NaN, Inf and values beyond the float range are errors at their line:column", "[csv]") {
  const auto ds = errorsOf("a, b\n1, nan\n# comment\n\ninf,2\n-1e39, 3\n1e38,-infinity\n0.5,1\n");
  REQUIRE(ds.size() == 4);
  CHECK(where(ds[0]) == "E-CSV-NUMBER@2:4");
  CHECK(where(ds[1]) == "E-CSV-NUMBER@5:1");
  CHECK(where(ds[2]) == "E-CSV-NUMBER@6:1");
  CHECK(where(ds[3]) == "E-CSV-NUMBER@7:6");
  CHECK(ds[0].message.find("finite") != std::string::npos);
  CHECK(ds[2].message.find("32-bit float") != std::string::npos);
}

TEST_CASE("csv: a binary field is quoted as a short printable excerpt", "[csv]") {
  std::string junk;
  for (int i = 0; i < 100000; ++i) junk += static_cast<char>(i % 251 == 10 || i % 251 == 44 ? 1 : i % 251);
  const auto ds = errorsOf("a,b\n1," + junk + "\n");
  REQUIRE(ds.size() == 1);
  CHECK(where(ds[0]) == "E-CSV-NUMBER@2:3");
  CHECK(ds[0].message.size() < 200);
  for (char c : ds[0].message) CHECK((c >= 0x20 && c < 0x7F));
  CHECK(quotedExcerpt(std::string("ab\0\xff", 4)) == "ab\\x00\\xff");
  CHECK(quotedExcerpt(std::string(50, 'x')) == std::string(40, 'x') + "...");
}

TEST_CASE("csv: errors stop after a bound, and so does a line without an end", "[csv]") {
  std::string text = "a\n";
  for (int i = 0; i < 1000; ++i) text += "x\n";
  CHECK(errorsOf(text).size() == kMaxCsvErrors);
  const auto ds = errorsOf("a\n" + std::string(kMaxCsvLineBytes + 10, '1'));
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == "E-CSV-LINE-TOO-LONG");
  CHECK(ds[0].message.size() < 300);
}

TEST_CASE("csv: a file is read row by row with each row's line, the same as in memory", "[csv]") {
  const fs::path file = fs::temp_directory_path() / ("mb-csv-" + std::to_string(::getpid()) + ".csv");
  std::string text = "# rows\nx,y\n";
  for (int i = 0; i < 30000; ++i) text += std::to_string(i) + ", " + std::to_string(i * 0.5) + "\r\n";
  std::ofstream(file, std::ios::binary) << text << "7,8";  // the last line has no newline
  CsvReader reader = CsvReader::open(file.string());
  CHECK(reader.header().names == std::vector<std::string>{"x", "y"});
  CHECK(reader.header().line == 2);
  std::vector<double> row;
  int line = 0, rows = 0;
  bool inOrder = true;
  while (reader.next(row, line)) {
    if (rows < 30000) inOrder = inOrder && row[0] == rows && row[1] == rows * 0.5 && line == rows + 3;
    ++rows;
  }
  CHECK(inOrder);
  CHECK(rows == 30001);
  CHECK(row == std::vector<double>{7, 8});
  CHECK(reader.errors().empty());
  fs::remove(file);
}

TEST_CASE("csv: columns are put in the expected order; unknown and missing ones are located", "[csv]") {
  const CsvTable t = parseCsv("b,a\n2,1\n", "in.csv");
  CHECK(selectColumns(t, {"a", "b"}) == std::vector<std::vector<double>>{{1, 2}});
  try {
    columnOrder(t.header, {"a", "c"});
    FAIL("no error");
  } catch (const DiagnosticError& e) {
    REQUIRE(e.diagnostics().size() == 2);
    CHECK(where(e.diagnostics()[0]) == "E-CSV-COLUMN@1:1");
    CHECK(e.diagnostics()[1].message.find("missing column(s): c") != std::string::npos);
  }
}
