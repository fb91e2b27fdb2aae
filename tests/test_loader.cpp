// Material JSON loader: one test per diagnostic code, each checking the code, the exact
// line:column, and the key parts of the message. Materials are inline strings so the
// positions can be read off the test itself (line 1 is the line with the opening brace).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fake_library.hpp"
#include "load/material_desc.hpp"
#include "support/material_fixtures.hpp"

using mb::Diagnostic;
using mb::DiagnosticError;

namespace {

const mb::ShaderLibrary& fakeLib() {
  static mb::test::FakeLibrary files;
  static mb::ShaderLibrary lib = mb::ShaderLibrary::load(files.root());
  return lib;
}

// All diagnostics of parsing `text` as "m.json" (empty if it parses).
std::vector<Diagnostic> errorsOf(const std::string& text) {
  try {
    mb::parseMaterialJson(text, "m.json", fakeLib());
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

void requireAt(const Diagnostic& d, int line, int column) {
  INFO(mb::formatDiagnostic(d));
  CHECK(d.where.file == "m.json");
  CHECK(d.where.line == line);
  CHECK(d.where.column == column);
}

using Catch::Matchers::Contains;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;

}  // namespace

TEST_CASE("valid material parses to the expected MaterialDesc", "[loader]") {
  const std::string text = R"({
  "name": "gold_filament",
  "description": "polished gold",
  "model": "standard",
  "bricks": {
    "specular_d": "d_beckmann",
    "fresnel": "f_schlick"
  },
  "parameters": {
    "roughness": {"type": "float", "default": 0.3, "range": [0.1, 0.9]},
    "baseColor": {"type": "vec3", "default": [1.0, 0.78, 0.34], "constant": true}
  }
})";
  mb::MaterialDesc m = mb::parseMaterialJson(text, "m.json", fakeLib());
  CHECK(m.name == "gold_filament");
  CHECK(m.description == "polished gold");
  CHECK(m.model == "standard");
  CHECK(m.sourceFile == "m.json");
  CHECK(m.bricks == std::map<std::string, std::string>{{"specular_d", "d_beckmann"}, {"fresnel", "f_schlick"}});
  CHECK(m.brickLocations.at("specular_d").line == 6);
  CHECK(m.brickLocations.at("specular_d").column == 19);
  CHECK(m.brickLocations.at("fresnel").line == 7);
  CHECK(m.brickLocations.at("fresnel").column == 16);

  // One entry per model input, in the model's order (baseColor, metallic, roughness).
  REQUIRE(m.params.size() == 3);
  const auto& base = m.params[0];
  CHECK(base.name == "baseColor");
  CHECK(base.type == mb::ValueType::Vec3);
  CHECK(base.value == std::vector<double>{1.0, 0.78, 0.34});
  CHECK(base.constant);
  CHECK(base.range.lo == 0.0);
  CHECK(base.range.hi == 1.0);
  CHECK(base.where.line == 11);
  CHECK(base.where.column == 5);

  const auto& metallic = m.params[1];  // not listed: a constant at the model's default
  CHECK(metallic.name == "metallic");
  CHECK(metallic.type == mb::ValueType::Float);
  CHECK(metallic.value == std::vector<double>{0.0});
  CHECK(metallic.constant);
  CHECK(metallic.range.hi == 1.0);

  const auto& rough = m.params[2];
  CHECK(rough.name == "roughness");
  CHECK(rough.value == std::vector<double>{0.3});
  CHECK_FALSE(rough.constant);
  CHECK(rough.range.lo == 0.1);
  CHECK(rough.range.hi == 0.9);
  CHECK(rough.where.line == 10);
  CHECK(rough.where.column == 5);
}

TEST_CASE("E-JSON-SYNTAX: invalid JSON is reported at the offending character", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-JSON-SYNTAX");
  requireAt(d, 3, 1);
  CHECK_THAT(d.message, Contains("unexpected '}'"));
}

TEST_CASE("E-MISSING-FIELD: a required top-level field is absent", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-MISSING-FIELD");
  requireAt(d, 1, 1);  // the enclosing object: the absent key has no position
  CHECK_THAT(d.message, Equals("material is missing required field 'model'"));
}

TEST_CASE("E-MISSING-FIELD: a slot of the model has no brick", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx"}
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-MISSING-FIELD");
  requireAt(d, 4, 13);
  CHECK_THAT(d.message, Contains("slot 'fresnel'"));
  CHECK_THAT(d.message, Contains("one of 'f_schlick'"));
}

TEST_CASE("E-UNKNOWN-FIELD: unknown top-level field suggests the closest name", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "brick": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  auto d = mb::test::theOne(ds, "E-UNKNOWN-FIELD");
  requireAt(d, 4, 3);
  CHECK_THAT(d.message, Contains("unknown field 'brick'"));
  CHECK(d.suggestion == "did you mean 'bricks'?");
}

TEST_CASE("E-UNKNOWN-FIELD: unknown parameter suggests a model input", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "parameters": {
    "roughnes": {"type": "float", "default": 0.3}
  }
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-UNKNOWN-FIELD");
  requireAt(d, 6, 5);
  CHECK_THAT(d.message, Contains("unknown parameter 'roughnes'"));
  CHECK(d.suggestion == "did you mean 'roughness'?");
}

TEST_CASE("E-UNKNOWN-SLOT: a bricks key that is not a slot of the model", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_dd": "d_ggx", "fresnel": "f_schlick"}
})");
  auto d = mb::test::theOne(ds, "E-UNKNOWN-SLOT");
  requireAt(d, 4, 14);
  CHECK_THAT(d.message, Contains("unknown slot 'specular_dd'"));
  CHECK(d.suggestion == "did you mean 'specular_d'?");
}

TEST_CASE("E-UNKNOWN-MODEL: unknown shading model suggests the closest", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standart",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-UNKNOWN-MODEL");
  requireAt(d, 3, 12);
  CHECK_THAT(d.message, Equals("unknown shading model 'standart': the library has 'standard'"));
  CHECK(d.suggestion == "did you mean 'standard'?");
}

TEST_CASE("E-UNKNOWN-BRICK: unknown brick id suggests close ids, the slot's first", "[loader]") {
  SECTION("a typo of a brick of the slot") {
    auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_gxx", "fresnel": "f_schlick"}
})");
    REQUIRE(ds.size() == 1);
    auto d = mb::test::theOne(ds, "E-UNKNOWN-BRICK");
    requireAt(d, 4, 28);
    CHECK_THAT(d.message, Equals("unknown brick 'd_gxx' for slot 'specular_d': expected one of "
                                 "'d_ggx', 'd_beckmann'"));
    CHECK(d.suggestion == "did you mean 'd_ggx'?");
  }
  SECTION("nothing of the slot is close: ids of other slots are suggested") {
    auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "schlick", "fresnel": "f_schlick"}
})");
    auto d = mb::test::theOne(ds, "E-UNKNOWN-BRICK");
    requireAt(d, 4, 28);
    CHECK(d.suggestion == "did you mean 'f_schlick'?");
  }
}

TEST_CASE("E-BRICK-WRONG-SLOT: a brick of another slot", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "f_schlick", "fresnel": "f_schlick"}
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-BRICK-WRONG-SLOT");
  requireAt(d, 4, 28);
  CHECK_THAT(d.message, Equals("brick 'f_schlick' fills slot 'fresnel', expected a 'specular_d' "
                               "brick: one of 'd_ggx', 'd_beckmann'"));
}

TEST_CASE("E-PARAM-TYPE: declared type or default shape differs from the model input", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "parameters": {
    "roughness": {"type": "vec3", "default": 0.3},
    "metallic": {"type": "float", "default": "high"},
    "baseColor": {"type": "vec3", "default": [1.0, 0.5]}
  }
})");
  REQUIRE(ds.size() == 3);
  for (const auto& d : ds) CHECK(d.code == "E-PARAM-TYPE");
  requireAt(ds[0], 6, 27);
  CHECK_THAT(ds[0].message, Equals("parameter 'roughness' is declared 'vec3' but model input "
                                   "'roughness' is a float"));
  requireAt(ds[1], 7, 46);
  CHECK_THAT(ds[1].message, Equals("'parameters.metallic.default' must be a float (a number), found string"));
  requireAt(ds[2], 8, 46);
  CHECK_THAT(ds[2].message, Equals("'parameters.baseColor.default' must be a vec3 (an array of 3 "
                                   "numbers), found an array of 2"));
}

TEST_CASE("E-PARAM-RANGE: default outside its range, range outside the model's, lo > hi", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "parameters": {
    "roughness": {"type": "float", "default": 1.5},
    "metallic": {"type": "float", "default": 0.5, "range": [0.0, 2.0]},
    "baseColor": {"type": "vec3", "default": [0.5, 0.5, 0.5], "range": [0.9, 0.1]}
  }
})");
  REQUIRE(ds.size() == 3);
  for (const auto& d : ds) CHECK(d.code == "E-PARAM-RANGE");
  requireAt(ds[0], 6, 47);
  CHECK_THAT(ds[0].message, Equals("'parameters.roughness.default' = 1.5 is outside [0.0, 1.0], "
                                   "the range of model input 'roughness'"));
  requireAt(ds[1], 7, 60);
  CHECK_THAT(ds[1].message, Equals("'parameters.metallic.range' [0.0, 2.0] must lie inside the "
                                   "range [0.0, 1.0] of model input 'metallic'"));
  requireAt(ds[2], 8, 72);
  CHECK_THAT(ds[2].message, Contains("empty range: lo 0.9 > hi 0.1"));
}

TEST_CASE("E-PARAM-RANGE: a vector default is checked per component", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "parameters": {
    "baseColor": {"type": "vec3", "default": [0.5, 0.9, 0.5], "range": [0.2, 0.8]}
  }
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-PARAM-RANGE");
  requireAt(d, 6, 52);  // the second component
  CHECK_THAT(d.message, Equals("'parameters.baseColor.default[1]' = 0.9 is outside [0.2, 0.8], "
                               "the parameter's range"));
}

TEST_CASE("E-FIELD-TYPE: fields of the wrong JSON type", "[loader]") {
  auto ds = errorsOf(R"({
  "name": 5,
  "model": "standard",
  "bricks": ["d_ggx", "f_schlick"]
})");
  REQUIRE(ds.size() == 2);
  for (const auto& d : ds) CHECK(d.code == "E-FIELD-TYPE");
  requireAt(ds[0], 2, 11);
  CHECK_THAT(ds[0].message, Equals("'name' must be a string, found number"));
  requireAt(ds[1], 4, 13);
  CHECK_THAT(ds[1].message, Equals("'bricks' must be an object, found array"));
}

TEST_CASE("E-INVALID-NAME: material name that is not an identifier", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold filament",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  REQUIRE(ds.size() == 1);
  auto d = mb::test::theOne(ds, "E-INVALID-NAME");
  requireAt(d, 2, 11);
  CHECK_THAT(d.message, Contains("'gold filament'"));
  CHECK_THAT(d.message, Contains("[A-Za-z_][A-Za-z0-9_]*"));
}

TEST_CASE("all errors of a file are reported, in file order", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "9lives",
  "model": "standard",
  "bricks": {"specular_d": "d_gxx", "fresnel": "f_schlick"},
  "parameters": {
    "metallic": {"type": "float", "default": 2.0, "colour": 1}
  },
  "descripton": "typo"
})");
  REQUIRE(ds.size() == 5);
  CHECK(ds[0].code == "E-INVALID-NAME");
  CHECK(ds[1].code == "E-UNKNOWN-BRICK");
  CHECK(ds[2].code == "E-PARAM-RANGE");
  CHECK(ds[3].code == "E-UNKNOWN-FIELD");  // "colour" inside the parameter object
  CHECK(ds[3].where.line == 6);
  CHECK(ds[3].where.column == 51);
  CHECK(ds[4].code == "E-UNKNOWN-FIELD");
  CHECK(ds[4].suggestion == "did you mean 'description'?");
  for (size_t i = 1; i < ds.size(); ++i) {
    INFO(i);
    CHECK(std::make_pair(ds[i - 1].where.line, ds[i - 1].where.column) <=
          std::make_pair(ds[i].where.line, ds[i].where.column));
  }
}

TEST_CASE("loadMaterialJson reads a file and reports a missing one", "[loader]") {
  auto dir = std::filesystem::temp_directory_path() / "mb_loader_test";
  std::filesystem::create_directories(dir);
  auto path = (dir / "gold.json").string();
  std::ofstream(path) << R"({"name": "gold", "model": "standard",
 "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}})";
  auto m = mb::loadMaterialJson(path, fakeLib());
  CHECK(m.name == "gold");
  CHECK(m.sourceFile == path);
  CHECK(m.brickLocations.at("fresnel").file == path);
  CHECK(m.brickLocations.at("fresnel").line == 2);

  try {
    mb::loadMaterialJson((dir / "absent.json").string(), fakeLib());
    FAIL("expected DiagnosticError");
  } catch (const DiagnosticError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].code == "E-FILE-NOT-FOUND");
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("a material using each slot's first brick of the shipped library loads", "[loader]") {
  auto lib = mb::ShaderLibrary::load(mb::ShaderLibrary::defaultRoot());
  for (const auto& model : lib.models()) {
    nlohmann::json j = {{"name", "m_" + model.name}, {"model", model.name}, {"bricks", {}}};
    bool complete = true;
    for (const auto& role : model.coreRoles()) {
      auto ids = lib.bricksOfSlot(model.findRole(role)->slot);
      if (ids.empty())
        complete = false;  // slot still being filled in
      else
        j["bricks"][role] = ids.front();
    }
    if (!complete) continue;
    INFO(model.name);
    auto m = mb::parseMaterialJson(j.dump(2), "m.json", lib);
    size_t coreInputs = 0;
    for (const auto& in : model.inputs) coreInputs += in.feature.empty();
    CHECK(m.params.size() == coreInputs);
    for (const auto& p : m.params) CHECK(p.constant);
  }
}

// --- features, roles, user parameters and surface code (docs/formats.md) -------------------

namespace {

std::vector<Diagnostic> featureErrorsOf(const std::string& text) {
  return mb::test::diagnosticsOf([&] { mb::parseMaterialJson(text, "m.json", mb::test::featureLibrary()); });
}

}  // namespace

TEST_CASE("features enable their roles and inputs; roles with a default get it", "[loader]") {
  const std::string text = R"({
  "name": "coated",
  "model": "standard",
  "features": ["clearcoat"],
  "bricks": {"specular_d": "d_beckmann", "fresnel": "f_schlick", "clearcoat_d": "d_beckmann"},
  "parameters": {"clearCoat": {"type": "float", "default": 0.5, "range": [0.0, 1.0]}}
})";
  auto m = mb::parseMaterialJson(text, "m.json", mb::test::featureLibrary());
  CHECK(m.form == "json");
  CHECK(m.features == std::vector<std::string>{"clearcoat"});
  CHECK(m.has("clearcoat"));
  CHECK_FALSE(m.has("sheen"));
  // The environment-conditional role is included with its default; sheen_d is not (feature off).
  CHECK(m.bricks == std::map<std::string, std::string>{{"specular_d", "d_beckmann"},
                                                       {"fresnel", "f_schlick"},
                                                       {"env_fresnel", "f_schlick"},
                                                       {"clearcoat_d", "d_beckmann"}});
  REQUIRE(m.params.size() == 4);  // baseColor, metallic, roughness, clearCoat (no sheenColor)
  CHECK(m.params[3].name == "clearCoat");
  CHECK_FALSE(m.params[3].constant);
  CHECK(m.params[3].value == std::vector<double>{0.5});

  // Without the choice, the feature role takes the model's default.
  auto d = mb::parseMaterialJson(R"({"name": "c", "model": "standard", "features": ["clearcoat"],
    "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}})",
                                 "m.json", mb::test::featureLibrary());
  CHECK(d.bricks.at("clearcoat_d") == "d_ggx");
  CHECK(d.param("clearCoat")->constant);
  CHECK(d.param("clearCoat")->value == std::vector<double>{1.0});
}

TEST_CASE("features are listed in the model's order, whatever the file's", "[loader]") {
  auto m = mb::parseMaterialJson(R"({"name": "c", "model": "standard", "features": ["sheen", "clearcoat"],
    "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick", "sheen_d": "d_ggx"}})",
                                 "m.json", mb::test::featureLibrary());
  CHECK(m.features == std::vector<std::string>{"clearcoat", "sheen"});
}

TEST_CASE("E-UNKNOWN-FEATURE and E-DUPLICATE-NAME for features", "[loader]") {
  auto ds = featureErrorsOf(R"({
  "name": "c",
  "model": "standard",
  "features": ["clearcaot", "sheen", "sheen"],
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick", "sheen_d": "d_ggx"}
})");
  REQUIRE(ds.size() == 2);
  requireAt(ds[0], 4, 16);
  CHECK(ds[0].code == "E-UNKNOWN-FEATURE");
  CHECK_THAT(ds[0].message, Equals("unknown feature 'clearcaot': model 'standard' has 'clearcoat', 'sheen'"));
  CHECK(ds[0].suggestion == "did you mean 'clearcoat'?");
  requireAt(ds[1], 4, 38);
  CHECK(ds[1].code == "E-DUPLICATE-NAME");
  CHECK_THAT(ds[1].message, Contains("feature 'sheen' is enabled twice (first at m.json:4:29)"));
}

TEST_CASE("E-FEATURE-DISABLED: a role or an input of a feature the material does not enable", "[loader]") {
  auto ds = featureErrorsOf(R"({
  "name": "c",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick", "clearcoat_d": "d_ggx"},
  "parameters": {"sheenColor": {"type": "vec3", "default": [0.1, 0.9, 0.1]}}
})");
  REQUIRE(ds.size() == 2);
  CHECK(ds[0].code == "E-FEATURE-DISABLED");
  requireAt(ds[0], 4, 61);
  CHECK_THAT(ds[0].message, Equals("role 'clearcoat_d' needs feature 'clearcoat' of model 'standard': "
                                   "enable the feature or remove the role"));
  CHECK(ds[1].code == "E-FEATURE-DISABLED");
  requireAt(ds[1], 5, 18);
  CHECK_THAT(ds[1].message, Contains("input 'sheenColor' belongs to feature 'sheen'"));
}

TEST_CASE("E-MISSING-FIELD: a feature role without a default must be chosen", "[loader]") {
  auto ds = featureErrorsOf(R"({
  "name": "c",
  "model": "standard",
  "features": ["sheen"],
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  auto d = mb::test::theOne(ds, "E-MISSING-FIELD");
  requireAt(d, 5, 13);
  CHECK_THAT(d.message, Equals("bricks is missing role 'sheen_d' (slot 'specular_d') of model 'standard': "
                               "choose one of 'd_ggx', 'd_beckmann'"));
}

TEST_CASE("user parameters need surface code, a type, and a valid name", "[loader]") {
  SECTION("accepted beside surface code, after the model inputs, in file order, default range [0, 1]") {
    auto m = mb::parseMaterialJson(R"({
  "name": "tinted",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "surface": {"glsl": "void surface(inout MaterialInputs m, MaterialParams p) {\n  m.baseColor = p.tint * p.gain;\n}"},
  "parameters": {
    "tint": {"type": "vec3", "default": [0.2, 0.4, 0.6]},
    "roughness": {"type": "float", "default": 0.3},
    "gain": {"type": "float", "default": 2.0, "range": [0.0, 4.0], "constant": true}
  }
})",
                                   "m.json", mb::test::featureLibrary());
    REQUIRE(m.params.size() == 5);
    CHECK(m.params[2].name == "roughness");
    CHECK_FALSE(m.params[2].user);
    CHECK(m.params[3].name == "tint");  // user parameters in the file's order, not alphabetical
    CHECK(m.params[3].user);
    CHECK(m.params[3].type == mb::ValueType::Vec3);
    CHECK(m.params[3].range.lo == 0.0);
    CHECK(m.params[3].range.hi == 1.0);
    CHECK_FALSE(m.params[3].constant);
    CHECK(m.params[4].name == "gain");
    CHECK(m.params[4].constant);
    CHECK(m.params[4].range.hi == 4.0);
    // The GLSL's first line is on the JSON string's line, just after its opening quote.
    CHECK(m.surface.where.file == "m.json");
    CHECK(m.surface.where.line == 5);
    CHECK(m.surface.where.column == 24);
    CHECK(m.surface.glsl ==
          "void surface(inout MaterialInputs m, MaterialParams p) {\n  m.baseColor = p.tint * p.gain;\n}\n");
  }
  SECTION("without surface code a non-input name is unknown") {
    auto ds = featureErrorsOf(R"({
  "name": "c",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "parameters": {"tint": {"type": "vec3", "default": [0.2, 0.4, 0.6]}}
})");
    auto d = mb::test::theOne(ds, "E-UNKNOWN-FIELD");
    requireAt(d, 5, 18);
    CHECK_THAT(d.message, Contains("a parameter that is not a model input needs surface code"));
  }
  SECTION("bad names, a default outside [0, 1] without a range") {
    auto ds = featureErrorsOf(R"({
  "name": "c",
  "model": "standard",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
  "surface": {"glsl": "void surface(inout MaterialInputs m, MaterialParams p) {}"},
  "parameters": {
    "uniform": {"type": "float", "default": 0.5},
    "gl_Tint": {"type": "float", "default": 0.5},
    "two words": {"type": "float", "default": 0.5},
    "n": {"type": "float", "default": 0.5},
    "gain": {"type": "float", "default": 2.0},
    "tint": {"type": "vec4", "default": [1, 1, 1, 1]}
  }
})");
    REQUIRE(ds.size() == 6);
    CHECK(ds[0].code == "E-INVALID-NAME");
    CHECK_THAT(ds[0].message, Contains("'uniform' is a GLSL keyword"));
    CHECK(ds[1].code == "E-INVALID-NAME");
    CHECK_THAT(ds[1].message, Contains("reserved by GLSL"));
    CHECK(ds[2].code == "E-INVALID-NAME");
    CHECK(ds[3].code == "E-INVALID-NAME");
    CHECK_THAT(ds[3].message, Contains("already used by the generated code"));
    CHECK(ds[4].code == "E-PARAM-RANGE");
    requireAt(ds[4], 11, 42);
    CHECK_THAT(ds[4].message, Equals("'parameters.gain.default' = 2.0 is outside [0.0, 1.0], the default range "
                                     "[0, 1] of a user parameter (give it a range)"));
    CHECK(ds[5].code == "E-PARAM-TYPE");
    requireAt(ds[5], 12, 22);
    CHECK(ds[5].suggestion == "did you mean 'vec2', 'vec3'?");
  }
}

TEST_CASE("surface: a file inside the project, or errors naming what is wrong", "[loader]") {
  mb::test::ScratchDir dir("json_surface");
  const std::string glsl = "void surface(inout MaterialInputs m, MaterialParams p) {\n  m.roughness = 0.7;\n}\n";
  dir.write("shaders/velvet.surface.glsl", glsl);
  auto material = [&](const std::string& surface) {
    return R"({"name": "v", "model": "standard", "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"},
 "surface": )" +
           surface + "}";
  };
  SECTION("read relative to the material, located at its own first line") {
    auto path = dir.write("v.json", material(R"({"file": "shaders/velvet.surface.glsl"})"));
    auto m = mb::loadMaterialJson(path, mb::test::featureLibrary());
    CHECK(m.surface.glsl == glsl);
    CHECK(m.surface.where.file == dir.path("shaders/velvet.surface.glsl"));
    CHECK(m.surface.where.line == 1);
  }
  SECTION("E-PATH-ESCAPE: .. out of the project, or an absolute path") {
    dir.write("sub/v.json", material(R"({"file": "../shaders/velvet.surface.glsl"})"));
    auto ds =
        mb::test::diagnosticsOf([&] { mb::loadMaterialJson(dir.path("sub/v.json"), mb::test::featureLibrary()); });
    auto d = mb::test::theOne(ds, "E-PATH-ESCAPE");
    CHECK(d.where.file == dir.path("sub/v.json"));
    CHECK(d.where.line == 2);
    CHECK(d.where.column == 22);
    CHECK_THAT(d.message, Contains("leaves the project directory"));
    auto path = dir.write("abs.json", material(R"({"file": "/etc/passwd"})"));
    ds = mb::test::diagnosticsOf([&] { mb::loadMaterialJson(path, mb::test::featureLibrary()); });
    CHECK_THAT(mb::test::theOne(ds, "E-PATH-ESCAPE").message, StartsWith("absolute path '/etc/passwd'"));
  }
  SECTION("E-FILE-NOT-FOUND at the file value; both or neither of file and glsl") {
    auto path = dir.write("missing.json", material(R"({"file": "nope.glsl"})"));
    auto ds = mb::test::diagnosticsOf([&] { mb::loadMaterialJson(path, mb::test::featureLibrary()); });
    CHECK(mb::test::theOne(ds, "E-FILE-NOT-FOUND").where.line == 2);
    ds = featureErrorsOf(material(R"({"file": "a.glsl", "glsl": "void surface() {}"})"));
    mb::test::theOne(ds, "E-CONFLICTING-FIELDS");
    ds = featureErrorsOf(material("{}"));
    CHECK_THAT(mb::test::theOne(ds, "E-MISSING-FIELD").message, Contains("surface needs 'file'"));
  }
  SECTION("E-SURFACE-FUNCTION: the code must define surface()") {
    auto ds = featureErrorsOf(material(R"({"glsl": "void surfaces(inout MaterialInputs m) {}"})"));
    auto d = mb::test::theOne(ds, "E-SURFACE-FUNCTION");
    CHECK(d.where.line == 2);
    CHECK(d.where.column == 23);
  }
}

TEST_CASE("loadMaterialFile picks the form by extension", "[loader]") {
  mb::test::ScratchDir dir("load_file");
  auto json = dir.write("a.json", R"({"name": "a", "model": "standard",
 "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}})");
  auto mat = dir.write("b.MAT",
                       "#define MATERIAL b\n#define MODEL standard\n#define BRICK_specular_d d_ggx\n"
                       "#define BRICK_fresnel f_schlick\n");
  auto a = mb::loadMaterialFile(json, mb::test::featureLibrary());
  REQUIRE(a.size() == 1);
  CHECK(a[0].form == "json");
  auto b = mb::loadMaterialFile(mat, mb::test::featureLibrary());
  REQUIRE(b.size() == 1);
  CHECK(b[0].form == "macro");
  CHECK(b[0].name == "b");
  auto ds =
      mb::test::diagnosticsOf([&] { mb::loadMaterialFile(dir.write("c.yaml", "x"), mb::test::featureLibrary()); });
  CHECK_THAT(mb::test::theOne(ds, "E-UNSUPPORTED-FORMAT").message,
             Contains("'.yaml': expected .json (material JSON), .mat"));
  ds = mb::test::diagnosticsOf([&] { mb::loadMaterialFile(dir.path("absent.mat"), mb::test::featureLibrary()); });
  mb::test::theOne(ds, "E-FILE-NOT-FOUND");
  std::filesystem::create_directories(dir.path("folder.json"));
  ds = mb::test::diagnosticsOf([&] { mb::loadMaterialFile(dir.path("folder.json"), mb::test::featureLibrary()); });
  CHECK_THAT(mb::test::theOne(ds, "E-FILE-NOT-REGULAR").message, Contains("is a directory"));
}

TEST_CASE("hostile JSON never crashes or hangs the loader: one clean diagnostic", "[loader]") {
  const std::string valid =
      R"({"name": "a", "model": "standard", "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}})";
  struct Case {
    const char* what;
    std::string text;
    const char* code;
  };
  std::vector<Case> cases = {
      {"empty", "", "E-JSON-SYNTAX"},
      {"truncated", valid.substr(0, valid.size() / 2), "E-JSON-SYNTAX"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\0",
                   10) +
           "\xff\xfe",
       "E-JSON-SYNTAX"},
      {"deeply nested", std::string(200000, '[') + std::string(200000, ']'), "E-JSON-SYNTAX"},
      {"huge name",
       R"({"name": ")" + std::string(4 << 20, 'x') +
           R"(!", "model": "standard", "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}})",
       "E-INVALID-NAME"},
      {"not an object", "[1, 2, 3]", "E-FIELD-TYPE"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    auto ds = featureErrorsOf(c.text);
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == c.code);
    CHECK(ds[0].where.line >= 1);
    CHECK(mb::formatDiagnostic(ds[0]).size() < 400);  // one readable line, whatever the input
  }
}
