// The macro form (docs/macro-form.md): directives, values, surface code, includes, errors at
// file:line:column, and that a JSON and a macro description of one material resolve to the
// same MaterialDesc. Materials are inline strings so positions can be read off the test
// (line 1 is the first line of the string).
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "load/material_desc.hpp"
#include "support/material_fixtures.hpp"

using mb::Diagnostic;
using mb::test::featureLibrary;
using mb::test::requireAt;
using mb::test::theOne;
using Catch::Matchers::Contains;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;

namespace {

std::vector<Diagnostic> macroErrorsOf(const std::string& text) {
  return mb::test::diagnosticsOf([&] { mb::parseMaterialMacro(text, "m.mat", featureLibrary()); });
}

const std::string kVelvetSurface =
    "void surface(inout MaterialInputs m, MaterialParams p) {\n"
    "  m.baseColor = p.tint * (1.0 - p.fuzz);\n"
    "}\n";

const std::string kVelvetMacro =
    "// velvet.mat: the seed's green velvet\n"
    "#define MATERIAL velvet_green\n"
    "#define MODEL standard\n"
    "#define DESCRIPTION \"green velvet, \\\"soft\\\"\"\n"
    "#define FEATURE_sheen\n"
    "#define BRICK_specular_d d_beckmann   // a trailing comment\n"
    "  #  define BRICK_fresnel f_schlick\n"
    "#define BRICK_sheen_d d_ggx\n"
    "#define PARAM_sheenColor vec3(0.1, 0.9, 0.1) RANGE(0, 1)\n"
    "#define CONST_roughness 0.8\n"
    "#define PARAM_fuzz float(0.25) RANGE(0.0, 0.5)\n"
    "#define CONST_tint vec3(0.5)\n"
    "\n" +
    kVelvetSurface;

// The same material in JSON, its surface code in a file beside it.
const std::string kVelvetJson = R"({
  "name": "velvet_green",
  "description": "green velvet, \"soft\"",
  "model": "standard",
  "features": ["sheen"],
  "bricks": {"specular_d": "d_beckmann", "fresnel": "f_schlick", "sheen_d": "d_ggx"},
  "surface": {"file": "velvet.surface.glsl"},
  "parameters": {
    "sheenColor": {"type": "vec3", "default": [0.1, 0.9, 0.1], "range": [0, 1]},
    "roughness": {"type": "float", "default": 0.8, "constant": true},
    "fuzz": {"type": "float", "default": 0.25, "range": [0.0, 0.5]},
    "tint": {"type": "vec3", "default": [0.5, 0.5, 0.5], "constant": true}
  }
})";

}  // namespace

TEST_CASE("a macro-form material parses to the expected MaterialDesc", "[macro]") {
  auto m = mb::parseMaterialMacro(kVelvetMacro, "m.mat", featureLibrary());
  CHECK(m.form == "macro");
  CHECK(m.name == "velvet_green");
  CHECK(m.model == "standard");
  CHECK(m.description == "green velvet, \"soft\"");
  CHECK(m.features == std::vector<std::string>{"sheen"});
  CHECK(m.bricks == std::map<std::string, std::string>{{"specular_d", "d_beckmann"},
                                                       {"fresnel", "f_schlick"},
                                                       {"env_fresnel", "f_schlick"},
                                                       {"sheen_d", "d_ggx"}});
  CHECK(m.brickLocations.at("specular_d").line == 6);
  CHECK(m.brickLocations.at("specular_d").column == 26);
  CHECK(m.brickLocations.at("fresnel").column == 27);
  // Model inputs in the model's order, then user parameters in the file's order.
  REQUIRE(m.params.size() == 6);
  const char* names[] = {"baseColor", "metallic", "roughness", "sheenColor", "fuzz", "tint"};
  for (size_t i = 0; i < 6; ++i) CHECK(m.params[i].name == names[i]);
  CHECK(m.params[0].constant);  // unmentioned: the model's default
  CHECK(m.params[2].constant);
  CHECK(m.params[2].value == std::vector<double>{0.8});
  CHECK_FALSE(m.params[3].constant);
  CHECK(m.params[3].value == std::vector<double>{0.1, 0.9, 0.1});
  CHECK(m.params[3].where.line == 9);
  CHECK(m.params[3].where.column == 15);
  CHECK(m.params[4].user);
  CHECK(m.params[4].range.hi == 0.5);
  CHECK(m.params[5].user);
  CHECK(m.params[5].constant);
  CHECK(m.params[5].value == std::vector<double>{0.5, 0.5, 0.5});  // vec3(x) repeats x
  CHECK(m.surface.glsl == kVelvetSurface);
  CHECK(m.surface.where.file == "m.mat");
  CHECK(m.surface.where.line == 14);
}

TEST_CASE("JSON and macro descriptions of one material resolve to the same MaterialDesc", "[macro]") {
  mb::test::ScratchDir dir("macro_same");
  dir.write("velvet.surface.glsl", kVelvetSurface);
  auto json = mb::loadMaterialJson(dir.write("velvet.json", kVelvetJson), featureLibrary());
  auto macro = mb::loadMaterialMacro(dir.write("velvet.mat", kVelvetMacro), featureLibrary());
  mb::test::requireSameMaterial(json, macro);
  CHECK(json.surface.where.file == dir.path("velvet.surface.glsl"));
  CHECK(macro.surface.where.file == dir.path("velvet.mat"));

  SECTION("inline JSON surface code and CR LF line ends change nothing") {
    nlohmann::json j = nlohmann::json::parse(kVelvetJson);
    j["surface"] = {{"glsl", kVelvetSurface}};
    auto inlineJson = mb::parseMaterialJson(j.dump(2), "v.json", featureLibrary());
    mb::test::requireSameMaterial(inlineJson, macro);
    std::string crlf;
    for (char c : kVelvetMacro) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    mb::test::requireSameMaterial(mb::parseMaterialMacro(crlf, "v.mat", featureLibrary()), macro);
  }
}

// For every model of the shipped library: every feature on, every role chosen, every input
// set (half constants, half inputs), a user parameter and surface code, written both ways.
TEST_CASE("every shipped model: JSON and macro forms give the same MaterialDesc", "[macro]") {
  auto lib = mb::ShaderLibrary::load(mb::ShaderLibrary::defaultRoot());
  auto number = [](double x) { return nlohmann::json(x).dump(); };
  for (const auto& model : lib.models()) {
    INFO("model " << model.name);
    nlohmann::json j = {{"name", "all_" + model.name},
                        {"model", model.name},
                        {"features", nlohmann::json::array()},
                        {"bricks", nlohmann::json::object()},
                        {"parameters", nlohmann::json::object()}};
    std::string mat = "#define MATERIAL all_" + model.name + "\n#define MODEL " + model.name + "\n";
    for (const auto& f : model.features) {
      j["features"].push_back(f.name);
      mat += "#define FEATURE_" + f.name + "\n";
    }
    bool complete = true;
    for (const auto& r : model.roles) {
      auto ids = lib.bricksOfSlot(r.slot);
      if (ids.empty()) {
        complete = complete && !r.defaultBrick.empty();  // a slot still being filled in
        continue;
      }
      j["bricks"][r.role] = ids.back();
      mat += "#define BRICK_" + r.role + " " + ids.back() + "\n";
    }
    if (!complete) continue;
    bool constant = false;
    for (const auto& in : model.inputs) {
      constant = !constant;
      nlohmann::json p = {{"type", mb::toString(in.type)},
                          {"default", in.defaultValue},
                          {"constant", constant},
                          {"range", {in.range.lo, in.range.hi}}};
      if (in.type == mb::ValueType::Float) p["default"] = in.defaultValue[0];
      j["parameters"][in.name] = p;
      std::string value = mb::toString(in.type) + "(";
      for (size_t i = 0; i < in.defaultValue.size(); ++i) value += (i ? ", " : "") + number(in.defaultValue[i]);
      mat += std::string("#define ") + (constant ? "CONST_" : "PARAM_") + in.name + " " + value + ") RANGE(" +
             number(in.range.lo) + ", " + number(in.range.hi) + ")\n";
    }
    j["parameters"]["userGain"] = {{"type", "float"}, {"default", 0.25}};
    mat += "#define PARAM_userGain 0.25\n";
    const std::string surface = "void surface(inout MaterialInputs m, MaterialParams p) {\n}\n";
    j["surface"] = {{"glsl", surface}};
    mat += surface;
    auto fromJson = mb::parseMaterialJson(j.dump(2), "all.json", lib);
    auto fromMacro = mb::parseMaterialMacro(mat, "all.mat", lib);
    mb::test::requireSameMaterial(fromJson, fromMacro);
    CHECK(fromMacro.features.size() == model.features.size());
    CHECK(fromMacro.params.size() == model.inputs.size() + 1);
  }
}

TEST_CASE("macro-form syntax errors: every line's problem, at its column, in file order", "[macro]") {
  auto ds = macroErrorsOf(
      "#define MATERIAL gold\n"                     // 1
      "#define MODLE standard\n"                    // 2
      "#define MODEL standard\n"                    // 3
      "#define BRIK_fresnel f_schlick\n"            // 4
      "#define BRICK_specular_d d_ggx\n"            // 5
      "#define BRICK_fresnel f_schlick\n"           // 6
      "#define BRICK_fresnel f_schlick\n"           // 7
      "#define PARAM_roughness 0.3.5\n"             // 8
      "#define PARAM_metallic vec4(1, 2, 3, 4)\n"   // 9
      "#define PARAM_baseColor vec3(0.1, 0.2)\n"    // 10
      "#define CONST_clearCoat 0.5 RANGES(0, 1)\n"  // 11
      "#defne FEATURE_clearcoat\n"                  // 12
      "#define DESCRIPTION \"unterminated\n");      // 13
  REQUIRE(ds.size() == 9);
  CHECK(ds[0].code == "E-UNKNOWN-DIRECTIVE");
  requireAt(ds[0], "m.mat", 2, 9);
  CHECK(ds[0].suggestion == "did you mean 'MODEL'?");
  CHECK(ds[1].code == "E-UNKNOWN-DIRECTIVE");
  requireAt(ds[1], "m.mat", 4, 9);
  CHECK_THAT(ds[1].message, Contains("expected one of MATERIAL, MODEL, DESCRIPTION, FEATURE_<feature>"));
  CHECK_THAT(ds[1].suggestion, StartsWith("did you mean 'BRICK_fresnel'"));
  CHECK(ds[2].code == "E-DUPLICATE-DEFINITION");
  requireAt(ds[2], "m.mat", 7, 9);
  CHECK_THAT(ds[2].message, Equals("the brick of role 'fresnel' is defined twice (first at m.mat:6:9)"));
  CHECK(ds[3].code == "E-MACRO-SYNTAX");
  requireAt(ds[3], "m.mat", 8, 25);
  CHECK_THAT(ds[3].message, Equals("malformed number '0.3.5': unexpected '.'"));
  CHECK(ds[4].code == "E-PARAM-TYPE");
  requireAt(ds[4], "m.mat", 9, 24);
  CHECK(ds[4].suggestion == "did you mean 'vec2', 'vec3'?");
  CHECK(ds[5].code == "E-PARAM-TYPE");
  requireAt(ds[5], "m.mat", 10, 25);
  CHECK_THAT(ds[5].message, Equals("vec3(...) takes 1 or 3 numbers, found 2"));
  CHECK(ds[6].code == "E-MACRO-SYNTAX");
  requireAt(ds[6], "m.mat", 11, 29);
  CHECK(ds[6].suggestion == "did you mean 'RANGE'?");
  CHECK(ds[7].code == "E-UNKNOWN-DIRECTIVE");
  requireAt(ds[7], "m.mat", 12, 2);
  CHECK(ds[7].suggestion == "did you mean 'define'?");
  CHECK(ds[8].code == "E-MACRO-SYNTAX");
  requireAt(ds[8], "m.mat", 13, 21);
  CHECK_THAT(ds[8].message, Contains("unterminated string"));
}

TEST_CASE("macro-form structure errors", "[macro]") {
  SECTION("no MATERIAL, no MODEL") {
    auto ds = macroErrorsOf("// empty\n");
    REQUIRE(ds.size() == 2);
    for (const auto& d : ds) requireAt(d, "m.mat", 1, 1);
    CHECK_THAT(ds[0].message, Contains("#define MATERIAL <name>"));
    CHECK_THAT(ds[1].message, Contains("#define MODEL <model>"));
  }
  SECTION("a directive without '#', a function-like macro, a value after a feature, numbers") {
    auto ds = macroErrorsOf(
        "#define MATERIAL gold\n"
        "define MODEL standard\n"
        "#define MODEL(x) standard\n"
        "#define FEATURE_clearcoat 1\n"
        "#define PARAM_roughness 1e999\n"
        "#define PARAM_metallic nan\n"
        "#define PARAM_baseColor 0x1F\n"
        "#define BRICK_ d_ggx\n");
    REQUIRE(ds.size() == 8);  // the 7 lines, and MODEL never defined
    requireAt(ds[0], "m.mat", 1, 1);
    CHECK_THAT(ds[0].message, Contains("no model"));
    CHECK_THAT(ds[1].message, Equals("'define' without '#': expected '#define ...'"));
    requireAt(ds[2], "m.mat", 3, 14);
    CHECK_THAT(ds[2].message, Contains("function-like macros"));
    requireAt(ds[3], "m.mat", 4, 27);
    CHECK_THAT(ds[3].message, Contains("a feature takes no value"));
    CHECK_THAT(ds[4].message, Contains("out of the range of a double"));
    CHECK_THAT(ds[5].message, Contains("expected a value"));
    CHECK_THAT(ds[6].message, Contains("malformed number '0x1F'"));
    requireAt(ds[7], "m.mat", 8, 15);
    CHECK_THAT(ds[7].message, Equals("expected a name after 'BRICK_'"));
  }
  SECTION("GLSL preprocessor lines belong in the surface code") {
    auto ds = macroErrorsOf("#version 450\n#define MATERIAL a\n#define MODEL standard\n");
    auto d = theOne(ds, "E-UNKNOWN-DIRECTIVE");
    requireAt(d, "m.mat", 1, 2);
    CHECK_THAT(d.message, Contains("belong in the surface code"));
    // ... where they are plain GLSL.
    auto m = mb::parseMaterialMacro(
        "#define MATERIAL a\n#define MODEL standard\n#define BRICK_specular_d d_ggx\n"
        "#define BRICK_fresnel f_schlick\nconst float k = 2.0;\n#define TWO k\n"
        "void surface(inout MaterialInputs m, MaterialParams p) { m.roughness = TWO / 4.0; }\n",
        "m.mat", featureLibrary());
    CHECK(m.surface.where.line == 5);
    CHECK_THAT(m.surface.glsl, Contains("#define TWO k"));
  }
}

TEST_CASE("macro-form meaning errors come from the shared resolver, at the macro's columns", "[macro]") {
  auto ds = macroErrorsOf(
      "#define MATERIAL gold\n"
      "#define MODEL standard\n"
      "#define BRICK_specular_d d_gxx\n"
      "#define BRICK_fresnel f_schlick\n"
      "#define BRICK_clearcoat_d d_ggx\n"
      "#define PARAM_roughness 1.5\n"
      "#define PARAM_baseColor vec3(0.5, 1.5, 0.5)\n"
      "#define PARAM_tint vec3(0.5)\n"
      "#define CONST_metallic vec3(1.0)\n");
  REQUIRE(ds.size() == 6);
  CHECK(ds[0].code == "E-UNKNOWN-BRICK");
  requireAt(ds[0], "m.mat", 3, 26);
  CHECK(ds[0].suggestion == "did you mean 'd_ggx'?");
  CHECK(ds[1].code == "E-FEATURE-DISABLED");
  requireAt(ds[1], "m.mat", 5, 15);
  CHECK_THAT(ds[1].message, Contains("role 'clearcoat_d' needs feature 'clearcoat'"));
  CHECK(ds[2].code == "E-PARAM-RANGE");
  requireAt(ds[2], "m.mat", 6, 25);
  CHECK_THAT(ds[2].message, Equals("'roughness' = 1.5 is outside [0.0, 1.0], the range of model input 'roughness'"));
  CHECK(ds[3].code == "E-PARAM-RANGE");
  requireAt(ds[3], "m.mat", 7, 35);
  CHECK_THAT(ds[3].message, StartsWith("'baseColor[1]' = 1.5"));
  CHECK(ds[4].code == "E-UNKNOWN-FIELD");
  requireAt(ds[4], "m.mat", 8, 15);
  CHECK_THAT(ds[4].message, Contains("needs surface code"));
  CHECK(ds[5].code == "E-PARAM-TYPE");
  requireAt(ds[5], "m.mat", 9, 24);
  CHECK_THAT(ds[5].message, Equals("parameter 'metallic' is declared 'vec3' but model input 'metallic' is a float"));
}

TEST_CASE("#include: relative to the including file, read once, inside the project", "[macro]") {
  mb::test::ScratchDir dir("macro_include");
  const std::string head = "#define MATERIAL inc\n";
  dir.write("shared/model.mat", "#define MODEL standard\n#include \"bricks/choice.mat\"\n");
  dir.write("shared/bricks/choice.mat", "#define BRICK_specular_d d_ggx\n#define BRICK_fresnel f_schlick\n");
  auto load = [&](const std::string& name, const std::string& text) {
    std::string path = dir.write(name, text);
    return mb::test::diagnosticsOf([&] { mb::loadMaterialMacro(path, featureLibrary()); });
  };

  SECTION("nested includes and a second include of the same file") {
    auto path = dir.write("ok.mat", head + "#include \"shared/model.mat\"\n#include \"shared/model.mat\"\n");
    auto m = mb::loadMaterialMacro(path, featureLibrary());
    CHECK(m.model == "standard");
    CHECK(m.bricks.at("fresnel") == "f_schlick");
    CHECK(m.brickLocations.at("fresnel").file == dir.path("shared/bricks/choice.mat"));
    CHECK(m.brickLocations.at("fresnel").line == 2);
  }
  SECTION("E-FILE-NOT-FOUND at the #include") {
    auto ds = load("missing.mat", head + "#include \"shared/absent.mat\"\n");
    auto d = theOne(ds, "E-FILE-NOT-FOUND");
    requireAt(d, dir.path("missing.mat"), 2, 10);
  }
  SECTION("E-INCLUDE-CYCLE names the cycle") {
    dir.write("cycle/b.mat", "#include \"c.mat\"\n");
    dir.write("cycle/c.mat", "#include \"b.mat\"\n");
    auto ds = load("cycle/a.mat", head + "#define MODEL standard\n#include \"b.mat\"\n");
    auto d = theOne(ds, "E-INCLUDE-CYCLE");
    requireAt(d, dir.path("cycle/c.mat"), 1, 10);
    CHECK_THAT(d.message, Equals("include cycle: " + dir.path("cycle/b.mat") + " -> " + dir.path("cycle/c.mat") +
                                 " -> " + dir.path("cycle/b.mat")));
    ds = load("self.mat", head + "#include \"self.mat\"\n");
    CHECK_THAT(theOne(ds, "E-INCLUDE-CYCLE").message, Contains("self.mat -> "));
  }
  SECTION("E-PATH-ESCAPE: .., an absolute path, a symbolic link out of the project") {
    dir.write("outside.mat", "#define MODEL standard\n");
    std::filesystem::create_directories(dir.path("project"));
    std::filesystem::create_symlink(dir.path("outside.mat"), dir.path("project/link.mat"));
    auto ds = load("project/m.mat", head +
                                        "#include \"../outside.mat\"\n#include \"/etc/hostname\"\n"
                                        "#include \"sub/../../outside.mat\"\n#include \"link.mat\"\n");
    std::vector<Diagnostic> escapes;
    for (const auto& d : ds)
      if (d.code == "E-PATH-ESCAPE") escapes.push_back(d);
    REQUIRE(escapes.size() == 4);
    for (int i = 0; i < 4; ++i) requireAt(escapes[i], dir.path("project/m.mat"), i + 2, 10);
    CHECK_THAT(escapes[1].message, StartsWith("absolute path"));
  }
  SECTION("surface code only in the top-level file") {
    dir.write("code.mat", "#define MODEL standard\nvoid helper() {}\n");
    auto ds = load("top.mat", head + "#include \"code.mat\"\n");
    auto d = theOne(ds, "E-MACRO-SYNTAX");
    requireAt(d, dir.path("code.mat"), 2, 1);
  }
  SECTION("E-INCLUDE-DEPTH for a long chain") {
    for (int i = 0; i < 20; ++i)
      dir.write("chain/" + std::to_string(i) + ".mat", "#include \"" + std::to_string(i + 1) + ".mat\"\n");
    dir.write("chain/20.mat", "\n");
    auto ds = load("chain/top.mat", head + "#include \"0.mat\"\n");
    theOne(ds, "E-INCLUDE-DEPTH");
  }
}

TEST_CASE("hostile macro-form input never crashes or hangs the loader", "[macro]") {
  const std::string valid =
      "#define MATERIAL a\n#define MODEL standard\n#define BRICK_specular_d d_ggx\n"
      "#define BRICK_fresnel f_schlick\n";
  struct Case {
    const char* what;
    std::string text;
    const char* code;
  };
  std::vector<Case> cases = {
      {"empty", "", "E-MISSING-FIELD"},
      {"truncated in a directive", valid.substr(0, valid.size() - 12), "E-MACRO-SYNTAX"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\0",
                   10) +
           "#define",
       "E-MACRO-SYNTAX"},
      {"huge directive line", "#define MATERIAL " + std::string(4 << 20, 'x') + "!\n" + valid, "E-MACRO-SYNTAX"},
      {"huge unknown directive", "#define " + std::string(1 << 20, 'Q') + " 1\n" + valid, "E-UNKNOWN-DIRECTIVE"},
      {"deeply nested value", "#define PARAM_roughness " + std::string(100000, '(') + "\n" + valid, "E-MACRO-SYNTAX"},
      {"huge surface without surface()", valid + std::string(4 << 20, ' ') + "x;\n", "E-SURFACE-FUNCTION"},
      {"control characters", valid + "#define PARAM_roughness \x01\x02\n", "E-MACRO-SYNTAX"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    auto ds = macroErrorsOf(c.text);
    REQUIRE_FALSE(ds.empty());
    CHECK(std::any_of(ds.begin(), ds.end(), [&](const Diagnostic& d) { return d.code == c.code; }));
    for (const auto& d : ds) {
      CHECK(d.where.line >= 1);
      CHECK(mb::formatDiagnostic(d).size() < 400);  // one readable line, whatever the input
    }
  }
}
