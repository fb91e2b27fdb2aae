// Brick facts as data (docs/formats.md "<slot>/slot.json"): the facts the compiler acts on
// by brick (here: the fp16 twin) are read from the brick's
// manifest entry and checked with file:line:column errors.
#include <catch2/catch.hpp>

#include <algorithm>

#include "emit/precision.hpp"
#include "fake_library.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
using mb::test::FakeLibrary;
using Catch::Matchers::Contains;

namespace {

// The fake library's specular_d/slot.json with `from` replaced by `to` (first occurrence).
std::string fakeSlotD(const std::string& from, const std::string& to) {
  std::string text = test::fakeLibraryFiles().at("specular_d/slot.json");
  auto pos = text.find(from);
  REQUIRE(pos != std::string::npos);
  return text.replace(pos, from.size(), to);
}

std::vector<Diagnostic> loadErrors(const FakeLibrary& lib) {
  try {
    ShaderLibrary::load(lib.root());
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

// The single diagnostic of a load, checked for its code and file:line:column.
Diagnostic onlyError(const FakeLibrary& lib, const std::string& code, int line, int column) {
  auto ds = loadErrors(lib);
  INFO("diagnostics:\n" << (ds.empty() ? std::string("(none)") : DiagnosticError(ds).what()));
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == code);
  CHECK(ds[0].where.file == lib.path("specular_d/slot.json"));
  CHECK(ds[0].where.line == line);
  CHECK(ds[0].where.column == column);
  return ds[0];
}

}  // namespace

TEST_CASE("fp16_twin: read from the brick entry, checked against the slot's bricks", "[library][brick-data]") {
  const std::string twin = "\"geometry\": {\"NoV\": [0.01, 1.0]},\n      \"fp16_twin\": ";
  SECTION("declared: fp16 permutations bind the twin") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD("\"geometry\": {\"NoV\": [0.01, 1.0]},", twin + "\"d_beckmann\",")}});
    auto lib = ShaderLibrary::load(files.root());
    CHECK(lib.findBrick("d_ggx")->fp16Twin == "d_beckmann");
    CHECK(brickForPrecision(lib, "d_ggx", ShaderPrecision::Fp16) == "d_beckmann");
    CHECK(brickForPrecision(lib, "d_ggx", ShaderPrecision::Fp16Mediump) == "d_beckmann");
    CHECK(brickForPrecision(lib, "d_ggx", ShaderPrecision::Fp32) == "d_ggx");
    CHECK(brickForPrecision(lib, "d_beckmann", ShaderPrecision::Fp16) == "d_beckmann");
  }
  SECTION("a twin that is no brick of the slot") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD("\"geometry\": {\"NoV\": [0.01, 1.0]},", twin + "\"d_beckman\",")}});
    auto d = onlyError(files, "E-UNKNOWN-BRICK", 16, 20);
    CHECK_THAT(d.message,
               Contains("fp16_twin of 'd_ggx' names 'd_beckman', which is not a brick of slot 'specular_d'"));
    CHECK(d.suggestion == "did you mean 'd_beckmann'?");
  }
  SECTION("a twin of another slot") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD("\"geometry\": {\"NoV\": [0.01, 1.0]},", twin + "\"f_schlick\",")}});
    onlyError(files, "E-UNKNOWN-BRICK", 16, 20);
  }
  // The shipped library: Filament's fp16 roughness floor.
  CHECK(brickForPrecision(test::shippedLibrary(), "roughness_clamped", ShaderPrecision::Fp16) ==
        "roughness_clamped_fp16");
}
