// Material JSON loader: one test per diagnostic code, each checking the code, the exact
// line:column, and the key parts of the message. Materials are inline strings so the
// positions can be read off the test itself (line 1 is the line with the opening brace).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fake_library.hpp"
#include "load/material_desc.hpp"

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

// The one diagnostic with `code`; fails the test when there is not exactly one.
Diagnostic only(const std::vector<Diagnostic>& ds, const std::string& code) {
  std::vector<Diagnostic> hits;
  for (const auto& d : ds)
    if (d.code == code) hits.push_back(d);
  INFO("diagnostics:\n" << DiagnosticError(ds).what());
  REQUIRE(hits.size() == 1);
  return hits.front();
}

void requireAt(const Diagnostic& d, int line, int column) {
  INFO(mb::formatDiagnostic(d));
  CHECK(d.where.file == "m.json");
  CHECK(d.where.line == line);
  CHECK(d.where.column == column);
}

using Catch::Matchers::Contains;
using Catch::Matchers::Equals;

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
  CHECK(m.bricks == std::map<std::string, std::string>{{"specular_d", "d_beckmann"},
                                                       {"fresnel", "f_schlick"}});
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
  auto d = only(ds, "E-JSON-SYNTAX");
  requireAt(d, 3, 1);
  CHECK_THAT(d.message, Contains("unexpected '}'"));
}

TEST_CASE("E-MISSING-FIELD: a required top-level field is absent", "[loader]") {
  auto ds = errorsOf(R"({
  "name": "gold",
  "bricks": {"specular_d": "d_ggx", "fresnel": "f_schlick"}
})");
  REQUIRE(ds.size() == 1);
  auto d = only(ds, "E-MISSING-FIELD");
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
  auto d = only(ds, "E-MISSING-FIELD");
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
  auto d = only(ds, "E-UNKNOWN-FIELD");
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
  auto d = only(ds, "E-UNKNOWN-FIELD");
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
  auto d = only(ds, "E-UNKNOWN-SLOT");
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
  auto d = only(ds, "E-UNKNOWN-MODEL");
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
    auto d = only(ds, "E-UNKNOWN-BRICK");
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
    auto d = only(ds, "E-UNKNOWN-BRICK");
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
  auto d = only(ds, "E-BRICK-WRONG-SLOT");
  requireAt(d, 4, 28);
  CHECK_THAT(d.message, Equals("brick 'f_schlick' fills slot 'fresnel', expected a 'specular_d' "
                               "brick: one of 'd_ggx', 'd_beckmann'"));
}

TEST_CASE("E-PARAM-TYPE: declared type or default shape differs from the model input",
          "[loader]") {
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
  CHECK_THAT(ds[1].message,
             Equals("'parameters.metallic.default' must be a float (a number), found string"));
  requireAt(ds[2], 8, 46);
  CHECK_THAT(ds[2].message, Equals("'parameters.baseColor.default' must be a vec3 (an array of 3 "
                                   "numbers), found an array of 2"));
}

TEST_CASE("E-PARAM-RANGE: default outside its range, range outside the model's, lo > hi",
          "[loader]") {
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
  auto d = only(ds, "E-PARAM-RANGE");
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
  auto d = only(ds, "E-INVALID-NAME");
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
    for (const auto& slot : model.slots) {
      auto ids = lib.bricksOfSlot(slot);
      if (ids.empty()) complete = false;  // slot still being filled in
      else j["bricks"][slot] = ids.front();
    }
    if (!complete) continue;
    INFO(model.name);
    auto m = mb::parseMaterialJson(j.dump(2), "m.json", lib);
    CHECK(m.params.size() == model.inputs.size());
    for (const auto& p : m.params) CHECK(p.constant);
  }
}
