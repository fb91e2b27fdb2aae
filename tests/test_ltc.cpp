// The LTC table of the library (shaderlib/ltc/ggx.json, `matbricks ltc`), checked against the
// fitter that made it (compiler/ltc) and against the split-sum integrals the energy checks
// and the DFG LUT use (common/ibl_reference.hpp).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/cloth_dfg_reference.hpp"
#include "common/ibl_reference.hpp"
#include "core/diagnostics.hpp"
#include "ltc/ltc_table.hpp"
#include "support/cli_support.hpp"

using namespace mb;

namespace {

const ltc::Table& storedTable() {
  static const ltc::Table t = ltc::loadTable((test::sourceDir() / "shaderlib/ltc/ggx.json").string());
  return t;
}

const ltc::Table& storedSheenTable() {
  static const ltc::Table t = ltc::loadTable((test::sourceDir() / "shaderlib/ltc/charlie.json").string());
  return t;
}

// Entries across the table, re-fitted by the tests below.
const std::vector<std::pair<uint32_t, uint32_t>> kRefitProbes{{62, 0}, {50, 10}, {40, 32}, {30, 50}, {20, 60}, {8, 20}};

// Entry (i, j) fitted again from its stored rougher neighbour, as the fitter walks a column,
// reaches the stored entry's error (the comparison is explained where it is first used).
void checkRefitted(const ltc::Table& t, uint32_t i, uint32_t j) {
  const double r = ltc::tableRoughness(i, t.size), NoV = ltc::tableNoV(j, t.size);
  const ltc::LtcShape start = ltc::shapeOf(ltc::tableRoughness(i + 1, t.size), NoV, t.at(i + 1, j).minv(), t.settings);
  const ltc::LtcEntry refit = ltc::fitEntry(r, NoV, start, t.settings);
  const double storedError = ltc::fitError(r, NoV, ltc::shapeOf(r, NoV, t.at(i, j).minv(), t.settings), t.settings);
  INFO("entry (" << i << ", " << j << "): r " << r << ", n.v " << NoV << ": stored error " << storedError
                 << ", re-fitted " << refit.error);
  CHECK(storedError <= refit.error * (1 + 1e-4));
  CHECK(refit.error <= storedError * (1 + 1e-4));
}

}  // namespace

TEST_CASE("the library's LTC table is the fitter's, entry for entry", "[ltc]") {
  const ltc::Table& t = storedTable();
  REQUIRE(t.size == 64);
  REQUIRE(t.entries.size() == 64u * 64u);
  // Re-fit entries across the table, each from its stored rougher neighbour as the fitter
  // walks a column. Nelder-Mead from a start rounded to fp32 stops at a slightly different
  // point of the same minimum, so the two are compared by the fitter's own error, which is
  // flat (quadratic) there: fp32 rounding of the matrix (6e-8 relative) and the simplex's stop
  // (a spread of 1e-12 relative) move it by ~1e-6 relative (measured: 6 digits agree). A
  // table fitted to another lobe, axes or sample count is off by far more than the 1e-4 here.
  for (auto [i, j] : kRefitProbes) {
    checkRefitted(t, i, j);
    const double r = ltc::tableRoughness(i, t.size), NoV = ltc::tableNoV(j, t.size);
    // The magnitudes are the split-sum integrals, rounded to fp32.
    const ref::DfgIntegrals dfg = ref::dfgIntegrals(NoV, std::max(r * r, ltc::kMinAlpha));
    CHECK(t.at(i, j).norm == static_cast<float>(dfg.gv));
    CHECK(t.at(i, j).fresnel == static_cast<float>(dfg.gvFc));
  }
}

// The LTC stands for the lobe D V (n.l) as norm x D_M, with norm = Int D V (n.l), the DFG
// channel Int Gv that the energy checks and the LUT integrate. Over the whole upper hemisphere
// (a light filling the sky) it gives norm x (the share of D_M above the horizon): never more than
// the lobe's albedo, all of it where the lobe is symmetric about n (normal incidence), and less
// where D_M, a cosine under a linear map, cannot follow the lobe's cut at the horizon
// (grazing views of smooth lobes; docs/models/lights.md "LTC tables" gives the measured loss).
TEST_CASE("the LTC lobe's integral over the hemisphere is the directional albedo or less", "[ltc]") {
  const ltc::Table& t = storedTable();
  const ref::Vec3 n{0, 0, 1};
  for (uint32_t i = 0; i < t.size; ++i)
    for (uint32_t j = 0; j < t.size; ++j) {
      const double r = ltc::tableRoughness(i, t.size), NoV = ltc::tableNoV(j, t.size);
      const ref::ltc::Mat3 m = ref::ltc::inverse(t.at(i, j).minv());
      const double share = ref::ltc::fractionAbove(m, n);
      INFO("entry (" << i << ", " << j << "): r " << r << ", n.v " << NoV << ", share above the horizon " << share);
      CHECK(share <= 1.0);
      // At n.v = 1 the fitted M^-1 is diag(m00, 1, m22) up to fp32 rounding of its zeros: the
      // share is 1 to within that rounding.
      if (j == 0) CHECK(share >= 1.0 - 1e-6);
      // The albedo itself is stored, as an fp32 number.
      CHECK(t.at(i, j).norm > 0.0f);
      CHECK(t.at(i, j).norm <= 1.0f);
    }
}

// The sheen's table (charlie.json), checked as the specular one: entries fitted again from their
// stored rougher neighbours reach the stored error, and the magnitude is the DFG LUT's cloth
// channel (Charlie D, Ashikhmin V) rounded to fp32, with no Fresnel part.
TEST_CASE("the library's sheen LTC table is the fitter's, entry for entry", "[ltc]") {
  const ltc::Table& t = storedSheenTable();
  REQUIRE(t.settings.lobe == ltc::LobeKind::Charlie);
  REQUIRE(t.size == storedTable().size);
  REQUIRE(t.entries.size() == size_t{t.size} * t.size);
  for (auto [i, j] : kRefitProbes) {
    checkRefitted(t, i, j);
    const double r = ltc::tableRoughness(i, t.size), NoV = ltc::tableNoV(j, t.size);
    const double alpha = std::max(r * r, ltc::kMinCharlieAlpha);
    CHECK(t.at(i, j).norm == static_cast<float>(ref::clothDfgIntegral(NoV, alpha)));
    CHECK(t.at(i, j).fresnel == 0.0f);
  }
  // The specular table's fitter would not reproduce it (the lobe is recorded and read back).
  ltc::FitSettings ggx = t.settings;
  ggx.lobe = ltc::LobeKind::Ggx;
  const double r = ltc::tableRoughness(40, t.size), NoV = ltc::tableNoV(32, t.size);
  CHECK(ltc::fitError(r, NoV, ltc::shapeOf(r, NoV, t.at(40, 32).minv(), ggx), ggx) >
        2.0 * ltc::fitError(r, NoV, ltc::shapeOf(r, NoV, t.at(40, 32).minv(), t.settings), t.settings));
}

TEST_CASE("a malformed LTC table is refused with its file, line and column", "[ltc][bad-input]") {
  const auto dir = std::filesystem::temp_directory_path() / ("mb-ltc-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto refused = [&](const std::string& text) {
    const auto file = dir / "t.json";
    std::ofstream(file) << text;
    try {
      ltc::loadTable(file.string());
    } catch (const DiagnosticError& e) {
      return e.diagnostics().front().code + " " + std::to_string(e.diagnostics().front().where.line) + ":" +
             std::to_string(e.diagnostics().front().where.column);
    }
    return std::string("accepted");
  };
  CHECK(refused("{\"format\": \"other\"}") == "E-LTC-TABLE 1:12");
  CHECK(
      refused(
          "{\"format\": \"matbricks-ltc-table\", \"version\": 1, \"size\": 2,\n \"entries\": [[1, 0, 0, 1, 1, 0]]}") ==
      "E-LTC-TABLE 2:13");
  CHECK(refused("{\"format\": \"matbricks-ltc-table\", \"version\": 1, \"size\": 1, \"entries\": []}") ==
        "E-LTC-TABLE 1:57");
  CHECK(
      refused(
          "{\"format\": \"matbricks-ltc-table\", \"version\": 1, \"size\": 2,\n \"fit\": {\"lobe\": \"beckmann\"}}") ==
      "E-LTC-TABLE 2:18");
  std::filesystem::remove_all(dir);
}

TEST_CASE("matbricks ltc fits the same table on one thread and on two", "[ltc][cli]") {
  const auto dir = test::freshTempDir("ltc", "threads");
  const auto one = test::runCli("ltc -q --size 6 --samples 8 -j 1 -o " + (dir / "t.json").string());
  INFO(one.output);
  REQUIRE(one.exitCode == 0);
  const std::string first = test::readFile(dir / "t.json");
  const auto two = test::runCli("ltc -q --size 6 --samples 8 -j 2 -o " + (dir / "t.json").string());
  REQUIRE(two.exitCode == 0);
  CHECK(test::readFile(dir / "t.json") == first);
  const ltc::Table t = ltc::loadTable((dir / "t.json").string());
  CHECK(t.size == 6);
  CHECK(t.settings.samples == 8);
  CHECK(t.settings.lobe == ltc::LobeKind::Ggx);
  // --lobe charlie fits the sheen's lobe, and says so in the file.
  const auto sheen = test::runCli("ltc -q --lobe charlie --size 6 --samples 8 -o " + (dir / "s.json").string());
  REQUIRE(sheen.exitCode == 0);
  CHECK(ltc::loadTable((dir / "s.json").string()).settings.lobe == ltc::LobeKind::Charlie);
  CHECK(test::readFile(dir / "s.json") != first);
  // A lobe it does not fit is refused, and nothing is written.
  const auto unknown = test::runCli("ltc -q --lobe beckmann --size 2 -o " + (dir / "b.json").string());
  CHECK(unknown.exitCode != 0);
  CHECK(unknown.output.find("--lobe") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "b.json"));
  // A directory where the table should go is refused, and left as it was.
  std::filesystem::create_directories(dir / "d");
  const auto refused = test::runCli("ltc -q --size 2 -o " + (dir / "d").string());
  CHECK(refused.exitCode != 0);
  CHECK(refused.output.find("E-OUTPUT-NOT-FILE") != std::string::npos);
  CHECK(std::filesystem::is_directory(dir / "d"));
  std::filesystem::remove_all(dir);
}
