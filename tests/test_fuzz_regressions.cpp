// Every input the libFuzzer targets found (fuzz/regressions/<target>/, docs/fuzzing.md) and
// every shipped seed, replayed through the same target bodies in the normal build, so that a
// fixed finding stays fixed without clang or a sanitizer build.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "support/build_paths.hpp"
#include "support/pipeline_support.hpp"
#include "targets/fuzz_targets.hpp"

namespace fs = std::filesystem;

namespace {

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The seed files of `target` named by fuzz/seeds.txt ("<target> <dir>/*.<ext>" lines).
std::vector<fs::path> seedFiles(const std::string& target) {
  std::vector<fs::path> out;
  std::ifstream list(mb::test::fuzzDir() / "seeds.txt");
  std::string line;
  while (std::getline(list, line)) {
    std::istringstream fields(line);
    std::string name, glob;
    if (!(fields >> name >> glob) || name != target) continue;
    fs::path pattern = mb::test::sourceDir() / glob;
    for (const auto& e : fs::directory_iterator(pattern.parent_path()))
      if (e.is_regular_file() && e.path().extension() == pattern.extension()) out.push_back(e.path());
  }
  return out;
}

// fuzz/regressions/<target>/: the findings of past campaigns, each fixed (none yet: see
// docs/bad-inputs.md for the campaigns run).
std::vector<fs::path> regressionFiles(const std::string& target) {
  std::vector<fs::path> out;
  fs::path dir = mb::test::fuzzDir() / "regressions" / target;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) out.push_back(e.path());
  return out;
}

void replay(const mb::fuzz::Target& t, const fs::path& input) {
  std::string bytes = readBytes(input);
  INFO(t.name << ": " << input.string());
  REQUIRE_NOTHROW(t.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
}

}  // namespace

TEST_CASE("every kept fuzz finding loads or gives coded diagnostics", "[fuzz][regressions]") {
  for (const auto& t : mb::fuzz::targets())
    for (const auto& f : regressionFiles(t.name)) replay(t, f);
}

TEST_CASE("every fuzz seed loads or gives coded diagnostics", "[fuzz][seeds]") {
  for (const auto& t : mb::fuzz::targets()) {
    auto seeds = seedFiles(t.name);
    CHECK(!seeds.empty());
    for (const auto& f : seeds) replay(t, f);
  }
}

TEST_CASE("the fuzz oracle accepts success and coded diagnostics, and nothing else", "[fuzz]") {
  using mb::fuzz::expectLoadOrDiagnostics;
  using mb::fuzz::FuzzFinding;
  auto coded = [](std::string code, std::string file) {
    return [=] { throw mb::DiagnosticError({{mb::Severity::Error, code, {file, 1, 1}, "bad", ""}}); };
  };
  REQUIRE_NOTHROW(expectLoadOrDiagnostics([] {}));
  REQUIRE_NOTHROW(expectLoadOrDiagnostics(coded("E-JSON-SYNTAX", "m.json")));
  REQUIRE_THROWS_AS(expectLoadOrDiagnostics(coded("E-JSON-SYNTAX", "")), FuzzFinding);
  REQUIRE_THROWS_AS(expectLoadOrDiagnostics(coded("oops", "m.json")), FuzzFinding);
  REQUIRE_THROWS_AS(expectLoadOrDiagnostics([] { throw mb::DiagnosticError({}); }), FuzzFinding);
  REQUIRE_THROWS_AS(expectLoadOrDiagnostics([] { throw std::out_of_range("vector::at"); }), FuzzFinding);
  // The csv target: a table without its columns (n, v, l, alpha) is a coded error, not a finding.
  const std::string csv = "x,y\n1,2\n";
  REQUIRE_NOTHROW(mb::fuzz::target("csv").run(reinterpret_cast<const uint8_t*>(csv.data()), csv.size()));
  REQUIRE_THROWS_AS(mb::fuzz::target("nope"), std::invalid_argument);
}
