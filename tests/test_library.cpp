// Shader library: the shipped library loads and matches its references; a small fake library
// (tests/fake_library.hpp) with one injected mistake per test checks each diagnostic and its
// file:line:column.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <optional>

#include "support/build_paths.hpp"
#include "common/reference.hpp"
#include "fake_library.hpp"
#include "support/material_fixtures.hpp"
#include "library/shader_library.hpp"

using mb::Diagnostic;
using mb::DiagnosticError;
using mb::ShaderLibrary;
using mb::test::FakeLibrary;
using mb::test::requireAt;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;

namespace {

// A default fake-library file with the first occurrence of `from` replaced by `to`.
std::string edited(const std::string& file, const std::string& from, const std::string& to) {
  std::string text = mb::test::fakeLibraryFiles().at(file);
  auto pos = text.find(from);
  REQUIRE(pos != std::string::npos);
  return text.replace(pos, from.size(), to);
}

// The diagnostics of loading a fake library with `overrides` (empty if it loads).
std::vector<Diagnostic> errorsOf(const FakeLibrary& lib) {
  try {
    ShaderLibrary::load(lib.root());
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace

TEST_CASE("value types: component counts, names, parsing", "[library]") {
  using mb::ValueType;
  CHECK(mb::componentCount(ValueType::Float) == 1);
  CHECK(mb::componentCount(ValueType::Vec2) == 2);
  CHECK(mb::componentCount(ValueType::Vec3) == 3);
  CHECK(mb::componentCount(ValueType::Geometry) == 9);  // n, v, l
  for (auto t : {ValueType::Float, ValueType::Vec2, ValueType::Vec3, ValueType::Geometry})
    CHECK(mb::parseValueType(mb::toString(t)) == t);
  CHECK(mb::toString(ValueType::Geometry) == "Geometry");
  CHECK_FALSE(mb::parseValueType("vec4").has_value());
  CHECK_FALSE(mb::parseValueType("Float").has_value());
}

TEST_CASE("the shipped library loads without errors", "[library]") {
  ShaderLibrary lib;
  try {
    lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  } catch (const DiagnosticError& e) {
    FAIL(e.what());
  }
  REQUIRE(lib.findModel("standard"));
  REQUIRE(lib.findBrick("d_ggx"));
  CHECK(lib.findBrick("d_ggx")->file == "specular_d/d_ggx.glsl");
  CHECK(lib.findModel("standard")->skeleton == "models/standard.glsl");
  // Slots keep the manifest's order, and bricks are grouped by slot in that order.
  std::vector<std::string> slotOrder;
  for (const auto& b : lib.bricks())
    if (slotOrder.empty() || slotOrder.back() != b.slot) slotOrder.push_back(b.slot);
  std::vector<std::string> manifestOrder;
  for (const auto& s : lib.slots())
    if (!lib.bricksOfSlot(s.name).empty()) manifestOrder.push_back(s.name);
  CHECK(slotOrder == manifestOrder);
}

TEST_CASE("every brick has a reference matching its slot signature", "[library]") {
  auto lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  for (const auto& brick : lib.bricks()) {
    INFO("brick " << brick.id << " (slot " << brick.slot << ")");
    const mb::ref::Reference* ref = mb::ref::Registry::references().find(brick.id);
    REQUIRE(ref != nullptr);
    const mb::Slot* slot = lib.findSlot(brick.slot);
    REQUIRE(slot != nullptr);
    std::vector<mb::ValueType> slotTypes;
    for (const auto& p : slot->params) slotTypes.push_back(p.type);
    CHECK(ref->params == slotTypes);
    CHECK(ref->returns == slot->returns);
  }
}

TEST_CASE("a fake library loads into the expected data", "[library]") {
  FakeLibrary files;
  auto lib = ShaderLibrary::load(files.root());
  CHECK(lib.brickIds() == std::vector<std::string>{"d_ggx", "d_beckmann", "f_schlick"});
  CHECK(lib.bricksOfSlot("specular_d") == std::vector<std::string>{"d_ggx", "d_beckmann"});
  REQUIRE(lib.slots().size() == 2);
  const mb::Slot& sd = lib.slots()[0];
  CHECK(sd.name == "specular_d");
  CHECK(sd.returns == mb::ValueType::Float);
  REQUIRE(sd.params.size() == 2);
  CHECK(sd.params[0].name == "g");
  CHECK(sd.params[0].type == mb::ValueType::Geometry);
  CHECK(lib.findSlot("fresnel")->returns == mb::ValueType::Vec3);

  const mb::Brick* ggx = lib.findBrick("d_ggx");
  REQUIRE(ggx);
  CHECK(ggx->slot == "specular_d");
  CHECK(ggx->file == "specular_d/d_ggx.glsl");
  CHECK(ggx->function == "mb_d_ggx");
  CHECK(ggx->requiredUnits == std::vector<std::string>{"common"});
  CHECK(ggx->domain.at("alpha").lo == 0.002);
  CHECK(ggx->geometry.NoV.lo == 0.01);
  CHECK(ggx->geometry.NoL.lo == mb::GeometryDomain{}.NoL.lo);  // default kept
  CHECK(ggx->tolerance.rel == 5e-4);
  CHECK(ggx->tolerance.reason == "fp32 half vector");
  CHECK(lib.findBrick("d_beckmann")->notes == "test brick");

  const mb::ShadingModel* model = lib.findModel("standard");
  REQUIRE(model);
  CHECK(model->skeleton == "models/standard.glsl");
  CHECK(model->coreRoles() == std::vector<std::string>{"specular_d", "fresnel"});
  CHECK(lightTypeNames(model->lights) == std::vector<std::string>{"dir"});
  REQUIRE(model->inputs.size() == 3);
  CHECK(model->inputs[0].name == "baseColor");
  CHECK(model->inputs[0].defaultValue == std::vector<double>{0.8, 0.8, 0.8});
  CHECK(model->inputs[2].range.hi == 1.0);

  REQUIRE(lib.findUnit("common"));
  CHECK(lib.findUnit("common")->file == "common/common.glsl");
  CHECK_THAT(lib.source("specular_d/d_ggx.glsl"), Contains("float mb_d_ggx("));
  CHECK(ShaderLibrary::displayPath("specular_d/d_ggx.glsl") == "shaderlib/specular_d/d_ggx.glsl");
  try {
    lib.source("nope.glsl");
    FAIL("expected DiagnosticError");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().at(0).code == "E-FILE-NOT-FOUND");
    CHECK(e.diagnostics().at(0).where.file == "shaderlib/nope.glsl");
  }
}

TEST_CASE("defaultRoot honours MATBRICKS_SHADERLIB", "[library]") {
  const char* old = std::getenv("MATBRICKS_SHADERLIB");
  std::optional<std::string> saved = old ? std::optional<std::string>(old) : std::nullopt;
  setenv("MATBRICKS_SHADERLIB", "/some/where", 1);
  CHECK(ShaderLibrary::defaultRoot() == std::filesystem::path("/some/where"));
  unsetenv("MATBRICKS_SHADERLIB");
  CHECK(ShaderLibrary::defaultRoot() == mb::test::buildSourceDir() / "shaderlib");
  if (saved) setenv("MATBRICKS_SHADERLIB", saved->c_str(), 1);
}

TEST_CASE("library: unknown key in slot.json", "[library]") {
  FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"returns\"", "\"return\"")}});
  auto ds = errorsOf(lib);
  auto d = mb::test::theOne(ds, "E-UNKNOWN-FIELD");
  requireAt(d, lib.path("fresnel/slot.json"), 4, 3);
  CHECK_THAT(d.message, Contains("unknown field 'return' in slot 'fresnel'"));
  CHECK(d.suggestion == "did you mean 'returns'?");
  requireAt(mb::test::theOne(ds, "E-MISSING-FIELD"), lib.path("fresnel/slot.json"), 1, 1);
}

TEST_CASE("library: unknown key in a brick", "[library]") {
  FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"citation\"", "\"citaton\"")}});
  auto ds = errorsOf(lib);
  auto d = mb::test::theOne(ds, "E-UNKNOWN-FIELD");
  requireAt(d, lib.path("fresnel/slot.json"), 12, 7);
  CHECK_THAT(d.message, Contains("in brick 'f_schlick'"));
  CHECK(d.suggestion == "did you mean 'citation'?");
}

TEST_CASE("library: tolerance reason missing or empty", "[library]") {
  SECTION("absent") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", ", \"reason\": \"pow5\"", "")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-MISSING-FIELD");
    requireAt(d, lib.path("fresnel/slot.json"), 15, 20);
    CHECK_THAT(d.message, Equals("tolerance is missing required field 'reason'"));
  }
  SECTION("empty") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"pow5\"", "\" \"")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-EMPTY-FIELD");
    requireAt(d, lib.path("fresnel/slot.json"), 15, 57);
    CHECK_THAT(d.message, Contains("'bricks[0].tolerance.reason' must not be empty"));
  }
}

TEST_CASE("library: duplicate brick id across slots", "[library]") {
  FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"f_schlick\"", "\"d_ggx\"")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-DUPLICATE-BRICK");
  requireAt(d, lib.path("fresnel/slot.json"), 8, 13);
  CHECK_THAT(d.message, Contains("already defined at " + lib.path("specular_d/slot.json") + ":8:13"));
}

TEST_CASE("library: brick requires an unknown unit", "[library]") {
  FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "[\"common\"]", "[\"comon\"]")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-UNIT");
  requireAt(d, lib.path("fresnel/slot.json"), 13, 20);
  CHECK(d.suggestion == "did you mean 'common'?");
}

TEST_CASE("library: slot name differs from its folder", "[library]") {
  FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"fresnel\"", "\"fresnell\"")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-NAME-MISMATCH");
  requireAt(d, lib.path("fresnel/slot.json"), 2, 11);
  CHECK_THAT(d.message, Contains("'fresnell' differs from its folder 'fresnel'"));
}

TEST_CASE("library: model names an unknown slot", "[library]") {
  FakeLibrary lib(
      {{"models/standard.json", edited("models/standard.json", "\"slot\": \"fresnel\"", "\"slot\": \"fresnl\"")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-SLOT");
  requireAt(d, lib.path("models/standard.json"), 10, 33);
  CHECK(d.suggestion == "did you mean 'fresnel'?");
}

TEST_CASE("library: model input default outside its range", "[library]") {
  FakeLibrary lib({{"models/standard.json", edited("models/standard.json", "\"default\": 0.5", "\"default\": 1.5")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-PARAM-RANGE");
  requireAt(d, lib.path("models/standard.json"), 15, 55);
}

TEST_CASE("library: model role with a default of another slot", "[library]") {
  FakeLibrary lib({{"models/standard.json", edited("models/standard.json", "\"slot\": \"fresnel\",",
                                                   "\"slot\": \"fresnel\", \"default\": \"d_ggx\",")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-BRICK");
  CHECK_THAT(d.message, Contains("'d_ggx' is not a brick of slot 'fresnel'"));
}

TEST_CASE("library: model role names an unknown light type", "[library]") {
  FakeLibrary lib({{"models/standard.json",
                    edited("models/standard.json", "\"lights\": [\"dir\"]", "\"lights\": [\"dir\", \"spto\"]")}});
  auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-NAME");
  CHECK_THAT(d.message, Contains("unknown light type 'spto'"));
  CHECK(d.suggestion == "did you mean 'spot'?");
}

TEST_CASE("library: domain must cover exactly the non-Geometry params", "[library]") {
  SECTION("a key that is not a parameter") {
    FakeLibrary lib(
        {{"fresnel/slot.json", edited("fresnel/slot.json", "[0.0, 1.0]}", "[0.0, 1.0], \"f90\": [0.0, 1.0]}")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-PARAM");
    requireAt(d, lib.path("fresnel/slot.json"), 14, 36);
    CHECK_THAT(d.message, Contains("'f90'"));
  }
  SECTION("a parameter without a range") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "{\"f0\": [0.0, 1.0]}", "{}")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-MISSING-DOMAIN");
    requireAt(d, lib.path("fresnel/slot.json"), 14, 17);
    CHECK_THAT(d.message, Contains("parameter 'f0'"));
  }
}

TEST_CASE("library: GLSL file missing or not defining the function", "[library]") {
  SECTION("missing file") {
    FakeLibrary lib({{"fresnel/f_schlick.glsl", std::string()}});  // deleted
    auto d = mb::test::theOne(errorsOf(lib), "E-FILE-NOT-FOUND");
    requireAt(d, lib.path("fresnel/slot.json"), 11, 15);
    CHECK_THAT(d.message, Contains("'f_schlick.glsl'"));
  }
  SECTION("function not defined") {
    FakeLibrary lib({{"fresnel/f_schlick.glsl", std::string("vec3 mb_f_schlick_x(vec3 f0) { return f0; }\n")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-MISSING-FUNCTION");
    requireAt(d, lib.path("fresnel/slot.json"), 10, 19);
  }
}

TEST_CASE("library: bad type, schema, missing folder, bad values and paths", "[library]") {
  SECTION("type") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"vec3\"", "\"vec4\"")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-UNKNOWN-TYPE");
    requireAt(d, lib.path("fresnel/slot.json"), 4, 14);
    CHECK_THAT(d.suggestion, Contains("'vec3'"));
  }
  SECTION("schema") {
    FakeLibrary lib({{"manifest.json", edited("manifest.json", "1", "2")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-SCHEMA-VERSION");
    requireAt(d, lib.path("manifest.json"), 2, 13);
  }
  SECTION("slot folder") {
    FakeLibrary lib({{"manifest.json", edited("manifest.json", "\"fresnel\"]", "\"fresnel\", \"sheen\"]")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-FILE-NOT-FOUND");
    requireAt(d, lib.path("manifest.json"), 4, 38);
    CHECK_THAT(d.message, Contains("sheen"));
  }
  SECTION("negative tolerance") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"abs\": 1e-6", "\"abs\": -1")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-INVALID-VALUE");
    requireAt(d, lib.path("fresnel/slot.json"), 15, 28);
  }
  SECTION("geometry range beyond a cosine") {
    FakeLibrary lib({{"specular_d/slot.json", edited("specular_d/slot.json", "[0.01, 1.0]", "[-1.5, 1.0]")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-PARAM-RANGE");
    requireAt(d, lib.path("specular_d/slot.json"), 15, 27);
    CHECK_THAT(d.message, Contains("'bricks[0].geometry.NoV' must lie inside [-1, 1]"));
  }
  SECTION("path outside the library") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"f_schlick.glsl\"", "\"../../x.glsl\"")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-INVALID-PATH");
    requireAt(d, lib.path("fresnel/slot.json"), 11, 15);
  }
  SECTION("slot listed twice") {
    FakeLibrary lib({{"manifest.json", edited("manifest.json", "\"fresnel\"]", "\"fresnel\", \"fresnel\"]")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-DUPLICATE-NAME");
    requireAt(d, lib.path("manifest.json"), 4, 38);
  }
  SECTION("JSON syntax in a slot file") {
    FakeLibrary lib({{"fresnel/slot.json", edited("fresnel/slot.json", "\"vec3\",", "\"vec3\"")}});
    auto d = mb::test::theOne(errorsOf(lib), "E-JSON-SYNTAX");
    CHECK(d.where.file == lib.path("fresnel/slot.json"));
    CHECK(d.where.line == 5);
  }
}

TEST_CASE("library: errors in several files are all reported", "[library]") {
  FakeLibrary lib({
      {"fresnel/slot.json", edited("fresnel/slot.json", "[\"common\"]", "[\"comon\"]")},
      {"specular_d/slot.json", edited("specular_d/slot.json", "\"fp32 half vector\"", "\"\"")},
  });
  auto ds = errorsOf(lib);
  REQUIRE(ds.size() == 2);
  requireAt(mb::test::theOne(ds, "E-EMPTY-FIELD"), lib.path("specular_d/slot.json"), 16, 56);
  requireAt(mb::test::theOne(ds, "E-UNKNOWN-UNIT"), lib.path("fresnel/slot.json"), 13, 20);
}
