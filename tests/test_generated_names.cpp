// User names against the generated code (docs/formats.md "Names"): the reserved set is derived
// from the code emitted for the material, so every name in it must be refused at the user's
// own file, line and column (never an E-GLSL at a generated line), and every name outside it,
// however often the library uses it for a local, must compile.
#include <catch2/catch.hpp>

#include <cfloat>
#include <set>

#include "compile/generated_names.hpp"
#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "load/glsl_names.hpp"
#include "support/material_fixtures.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

// worn_car_paint (standard + clearcoat, surface code) with the user parameters `params`
// ("name": {...} entries); its parameters object starts at line 6.
std::string paintJson(const std::string& params) {
  return R"({
  "name": "paint",
  "model": "standard",
  "features": ["clearcoat"],
  "bricks": {"roughness": "roughness_clamped", "diffuse": "diffuse_lambert", "specular_d": "d_ggx", "specular_v": "v_smith_ggx_correlated", "fresnel": "f_schlick"},
  "parameters": {
)" + params +
         R"(
  },
  "surface": {"glsl": "void surface(inout MaterialInputs m, MaterialParams p) {}"}
})";
}

std::string floatParam(const std::string& name) {
  return "    \"" + name + "\": {\"type\": \"float\", \"default\": 0.5}";
}

std::vector<Diagnostic> errorsOf(const std::string& json) {
  return test::diagnosticsOf([&] { parseMaterialJson(json, "paint.json", test::shippedLibrary()); });
}

std::map<std::string, GeneratedName> paintNames() {
  MaterialDesc m = parseMaterialJson(paintJson(floatParam("wear")), "paint.json", test::shippedLibrary());
  return generatedIdentifiers(test::shippedLibrary(), m);
}

// Every identifier token of `glsl` outside comments and not after a '.': a superset of what
// the code declares and uses.
std::set<std::string> identifierTokens(const std::string& glsl) {
  std::set<std::string> out;
  std::istringstream in(glsl);
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find("//"));
    if (line.find('#') != std::string::npos) continue;
    for (size_t i = 0; i < line.size();) {
      auto c = static_cast<unsigned char>(line[i]);
      if (std::isdigit(c)) {
        while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '.')) ++i;
      } else if (std::isalpha(c) || c == '_') {
        size_t start = i;
        while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_')) ++i;
        if (start == 0 || line[start - 1] != '.') out.insert(line.substr(start, i - start));
      } else {
        ++i;
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("the reserved names are derived from the generated code", "[names]") {
  const auto names = paintNames();
  // The issue's case and the wrapper functions' own names.
  for (const char* n : {"b",
                        "n",
                        "v",
                        "l",
                        "m",
                        "p",
                        "f",
                        "px",
                        "illuminance",
                        "surface",
                        "materialInputs",
                        "evaluateMaterial",
                        "preparePixel",
                        "ShadingFrame",
                        "ShadingPixel",
                        "MaterialInputs",
                        "MaterialParams",
                        "normalize",
                        "mbIn",
                        "mbPush",
                        "main"}) {
    INFO(n);
    CHECK(names.count(n) == 1);
  }
  CHECK_THAT(names.at("b").what, Catch::Contains("evaluateMaterial()"));
  CHECK(names.at("b").localOnly);
  CHECK(names.at("n").localOnly);
  CHECK_FALSE(names.at("normalize").localOnly);
  CHECK_FALSE(names.at("materialInputs").localOnly);
  CHECK_FALSE(names.at("ShadingFrame").localOnly);
  // Library globals come from glslang's AST, macros from the text.
  CHECK(std::any_of(names.begin(), names.end(),
                    [](const auto& e) { return e.second.what.find("a function of shaderlib/") == 0; }));
  CHECK(std::any_of(names.begin(), names.end(), [](const auto& e) { return e.second.what.find("a macro of") == 0; }));
  // Model inputs are the model's parameters, not collisions; the placeholder leaves no trace.
  CHECK(names.count("baseColor") == 0);
  CHECK(names.count("clearCoat") == 0);
  for (const auto& [name, g] : names) CHECK(name.find("placeholder") == std::string::npos);
}

TEST_CASE("every derived name is refused as a user parameter, at the name", "[names]") {
  const auto names = paintNames();
  REQUIRE(names.size() > 50);
  size_t checked = 0;
  for (const auto& [name, g] : names) {
    INFO(name << ": " << g.what);
    auto ds = errorsOf(paintJson(floatParam(name)));
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == "E-INVALID-NAME");
    CHECK(ds[0].where.file == "paint.json");
    CHECK(ds[0].where.line == 7);
    CHECK(ds[0].where.column == 5);
    ++checked;
  }
  CHECK(checked == names.size());
}

TEST_CASE("a user parameter named b is refused at its name, not at a generated line", "[names]") {
  auto ds = errorsOf(paintJson(floatParam("b")));
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == "E-INVALID-NAME");
  CHECK(ds[0].where.line == 7);
  CHECK_THAT(ds[0].message,
             Catch::Equals("parameter name 'b' is already used by the generated code (used in the generated "
                           "evaluateMaterial())"));
}

TEST_CASE("C++ keywords are refused as parameter names: the header declares them as members", "[names]") {
  for (const char* n : {"new", "delete", "private", "operator", "typename"}) {
    INFO(n);
    auto ds = errorsOf(paintJson(floatParam(n)));
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == "E-INVALID-NAME");
    CHECK_THAT(ds[0].message, Catch::Contains("C++ keyword"));
  }
}

namespace {

// `base` with a user parameter for every identifier of its emitted code (the library's locals
// and parameters, struct members, ...) and a few ordinary names that the derived set leaves
// free, and an empty surface(); each of its permutations must compile, at fp32 and fp16.
void compilesWithEveryFreeName(MaterialDesc base) {
  const ShaderLibrary& lib = test::shippedLibrary();
  const auto reserved = generatedIdentifiers(lib, base);
  std::set<std::string> candidates = {"tint", "gain", "scale", "wear", "dirt", "roughnessScale", "x", "a", "t"};
  for (Permutation perm : validationPermutationsFor(base, lib)) {
    auto tokens = identifierTokens(emitPermutation(lib, perm).glsl);
    candidates.insert(tokens.begin(), tokens.end());
  }
  for (const auto& p : base.params) candidates.erase(p.name);  // the model's inputs
  for (const auto& in : lib.findModel(base.model)->inputs) candidates.erase(in.name);
  size_t accepted = 0;
  for (const auto& name : candidates) {
    if (reserved.count(name) || !reservedNameReason(name).empty()) continue;
    base.params.push_back({.name = name, .value = {0.5}, .range = {0.0, 1.0}, .user = true, .where = {}});
    ++accepted;
  }
  base.surface = {"void surface(inout MaterialInputs m, MaterialParams p) {}\n", {"s.glsl", 1, 1}};
  INFO(base.model << ": " << accepted << " user parameters");
  REQUIRE(accepted > 40);  // the library's locals and parameters are not reserved
  for (Permutation perm : validationPermutationsFor(base, lib)) {
    for (Precision precision : allPrecisions()) {
      perm.precision = precision;
      EmittedShader s = emitPermutation(lib, perm);
      INFO(s.key);
      CHECK_NOTHROW(compileComputeGlsl(s.glsl, s.fileName, {ShaderStage::Compute, OptimizationLevel::O0, false}));
    }
  }
}

}  // namespace

TEST_CASE("every name outside the derived set compiles in every permutation", "[names]") {
  SECTION("standard, with clearcoat") {
    compilesWithEveryFreeName(parseMaterialJson(paintJson(floatParam("wear")), "paint.json", test::shippedLibrary()));
  }
  SECTION("cloth") { compilesWithEveryFreeName(test::shippedMaterial("velvet_green")); }
}

TEST_CASE("surface code may not declare a name the generated code uses", "[names]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto withSurface = [](const std::string& glsl) {
    return "#define MATERIAL s\n#define MODEL standard\n#define BRICK_roughness roughness_clamped\n#define "
           "BRICK_diffuse diffuse_lambert\n#define BRICK_specular_d d_ggx\n#define BRICK_specular_v "
           "v_smith_ggx_correlated\n#define BRICK_fresnel f_schlick\n#define PARAM_gain 0.5\n" +
           glsl;
  };
  SECTION("a macro and a function of the generated code, at the user's line and column") {
    auto ds = test::diagnosticsOf([&] {
      parseMaterialMacro(withSurface("vec3 emittedRadiance(ShadingPixel q) { return vec3(0.0); }\n"
                                     "#define f 2.0\n"
                                     "float helper(float x) { return x * f; }\n"
                                     "void surface(inout MaterialInputs m, MaterialParams p) {\n"
                                     "    m.roughness = helper(p.gain);\n"
                                     "}\n"),
                         "s.mat", lib);
    });
    REQUIRE(ds.size() == 2);
    CHECK(ds[0].code == "E-INVALID-NAME");
    CHECK(ds[0].where.line == 9);
    CHECK(ds[0].where.column == 6);
    CHECK_THAT(ds[0].message, Catch::Contains("surface code declares 'emittedRadiance'"));
    CHECK(ds[1].code == "E-INVALID-NAME");
    CHECK(ds[1].where.line == 10);
    CHECK(ds[1].where.column == 9);
    CHECK_THAT(ds[1].message, Catch::Contains("surface code declares 'f', which is already used by the generated "
                                              "code (used in the generated"));
  }
  SECTION("helpers, constants and structs of free names compile") {
    // `k` and `f` are locals of generated functions (a loop counter, the ShadingFrame): there
    // they shadow the user's globals, which is legal GLSL.
    MaterialDesc m = parseMaterialMacro(withSurface("const float k = 0.5;\n"
                                                    "float f(float x) { return x * k; }\n"
                                                    "const float kScale = 0.5;\n"
                                                    "struct Wear { float amount; };\n"
                                                    "float helper(Wear w) { return w.amount * kScale; }\n"
                                                    "void surface(inout MaterialInputs m, MaterialParams p) {\n"
                                                    "    m.roughness = f(helper(Wear(p.gain)));\n"
                                                    "}\n"),
                                        "s.mat", lib);
    for (Permutation perm : validationPermutationsFor(m, lib)) {
      EmittedShader s = emitPermutation(lib, perm);
      INFO(s.key);
      CHECK_NOTHROW(compileComputeGlsl(s.glsl, s.fileName, {ShaderStage::Compute, OptimizationLevel::O0, false}));
    }
  }
}

TEST_CASE("globalNamesOf finds what surface code declares at global scope", "[names]") {
  auto names = globalNamesOf(
      "// float commented(float x);\n#define TWICE(x) (2.0 * (x))\nconst float k = 1.0, j = 2.0;\nfloat arr[2];\n"
      "struct S { float inner; } s;\nvec3 fn(vec3 a) { float local = a.x; return vec3(local); }\n"
      "/* float hidden; */ float proto(float);\nlayout(constant_id = 0) const int spec = 1;\n");
  std::vector<std::string> got;
  for (const auto& n : names) got.push_back(n.name);
  CHECK(got == std::vector<std::string>{"TWICE", "k", "arr", "S", "s", "fn", "proto", "spec"});
  CHECK(names[0].line == 1);
  CHECK(names[0].column == 9);
  CHECK(names[5].line == 5);
  CHECK(names[5].column == 6);
}
