// Small input rules around names and paths: the depfile's escaping (read back the way Ninja's
// depfile parser reads it), --namespace as a C++ name, parameter values beyond fp32, and a
// material path with a newline, which ends up in comments and #line directives of the
// generated code.
#include <catch2/catch.hpp>

#include <fstream>

#include "compile/glsl_compiler.hpp"
#include "core/cpp_identifiers.hpp"
#include "emit/emitter.hpp"
#include "support/cli_support.hpp"
#include "support/material_fixtures.hpp"
#include "support/pipeline_support.hpp"
#include "write/depfile.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

// The file names of a depfile's first rule as Ninja reads them (src/depfile_parser.in.cc):
// 2N+1 backslashes and a space are N backslashes and a space, a backslash before '#' or ':'
// is dropped, "$$" is '$', other backslashes stay, and unescaped whitespace separates names.
std::vector<std::string> ninjaRead(const std::string& depfile) {
  std::vector<std::string> names;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) names.push_back(cur);
    cur.clear();
  };
  for (size_t i = 0; i < depfile.size();) {
    char c = depfile[i];
    if (c == '\\') {
      size_t n = 0;
      while (i + n < depfile.size() && depfile[i + n] == '\\') ++n;
      char next = i + n < depfile.size() ? depfile[i + n] : '\0';
      if (next == ' ' && n % 2 == 1) {
        cur.append(n / 2, '\\');
        cur += ' ';
        i += n + 1;
      } else if (next == '#' || next == ':') {
        cur.append(n - 1, '\\');
        cur += next;
        i += n + 1;
      } else if (next == '\n') {
        cur.append(n - 1, '\\');
        flush();
        i += n + 1;
      } else {
        cur.append(n, '\\');
        i += n;
      }
    } else if (c == '$' && i + 1 < depfile.size() && depfile[i + 1] == '$') {
      cur += '$';
      i += 2;
    } else if (c == ' ' || c == '\n' || c == '\t') {
      flush();
      ++i;
    } else {
      cur += c;
      ++i;
    }
  }
  flush();
  return names;
}

std::vector<Diagnostic> errorsOfJson(const std::string& json) {
  return test::diagnosticsOf([&] { parseMaterialJson(json, "m.json", test::shippedLibrary()); });
}

std::vector<Diagnostic> errorsOfMacro(const std::string& text) {
  return test::diagnosticsOf([&] { parseMaterialMacro(text, "m.mat", test::shippedLibrary()); });
}

}  // namespace

TEST_CASE("the depfile escapes what Make and Ninja would split or expand, and reads back as written", "[depfile]") {
  const std::vector<std::string> deps = {"/p/a b.json",   "/p/c#d.mat",   "/p/e$f.glsl",    "/p/g:h.json",
                                         "/p/i\\ j.json", "/p/k\\#l.mat", "/p/back\\slash", "/p/ünï.json"};
  const std::string target = "/out/my pkg/manifest.json";
  std::string text = makeDepfile(target, deps);
  INFO(text);
  std::vector<std::string> read = ninjaRead(text);
  REQUIRE(read.size() == deps.size() + 1);
  CHECK(read[0] == target + ":");  // the rule's colon ends the target
  for (size_t i = 0; i < deps.size(); ++i) CHECK(read[i + 1] == deps[i]);
}

TEST_CASE("the depfile refuses a path no escape can carry", "[depfile]") {
  for (const std::string bad :
       {"/p/new\nline.json", "/p/tab\tbed.json", "/p/cr\r.json", "/p/trailing\\", "/p/colon:"}) {
    INFO(bad);
    CHECK_FALSE(depfileRefusal(bad).empty());
    try {
      makeDepfile("/out/manifest.json", {"/p/ok.json", bad});
      FAIL("accepted");
    } catch (const DiagnosticError& e) {
      REQUIRE(e.diagnostics().size() == 1);
      CHECK(e.diagnostics()[0].code == "E-DEPFILE-PATH");
      CHECK(e.diagnostics()[0].where.file.find_first_of("\n\t\r") == std::string::npos);
    }
  }
  CHECK(depfileRefusal("/p/a b#c$d:e.json").empty());
}

TEST_CASE("compile --depfile with a material whose path has a space, '#', '$' and ':'", "[depfile]") {
  fs::path dir = test::freshTempDir("depfile", "names");
  fs::path odd = dir / "my mats#1 $x:y";
  fs::create_directories(odd);
  fs::copy_file(test::materialPath("worn_car_paint.json"), odd / "paint.json");
  auto r = test::runCli("compile -q --no-cache '" + (odd / "paint.json").string() + "' -o '" + (dir / "pkg").string() +
                        "' --depfile '" + (dir / "deps.d").string() + "'");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  std::vector<std::string> read = ninjaRead(test::readFile(dir / "deps.d"));
  REQUIRE(read.size() > 3);
  CHECK(std::find(read.begin(), read.end(), fs::absolute(odd / "paint.json").lexically_normal().generic_string()) !=
        read.end());
  for (size_t i = 1; i < read.size(); ++i) {
    INFO(read[i]);
    CHECK(fs::exists(read[i]));
  }
  fs::remove_all(dir);
}

TEST_CASE("compile --depfile refuses a material path with a tab before writing anything", "[depfile]") {
  fs::path dir = test::freshTempDir("depfile", "tab");
  fs::copy_file(test::materialPath("worn_car_paint.json"), dir / "pa\tint.json");
  auto r = test::runCli("compile -q --no-cache '" + (dir / "pa\tint.json").string() + "' -o '" +
                        (dir / "pkg").string() + "' --depfile '" + (dir / "deps.d").string() + "'");
  INFO(r.output);
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains("error[E-DEPFILE-PATH]"));
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(dir / "pkg"));
  CHECK_FALSE(fs::exists(dir / "deps.d"));
  fs::remove_all(dir);
}

TEST_CASE("the --namespace option is a C++ identifier or a nested a::b", "[names]") {
  for (const char* ok : {"engine", "my_engine::materials", "a::b::c", "_private", "ns2"}) {
    INFO(ok);
    CHECK(cppNamespaceRefusal(ok).empty());
  }
  for (const char* bad : {"", "a b", "a::", "::a", "a:::b", "1abc", "class", "a::new", "__x", "_Upper", "a::b__c",
                          "a-b", "a/b", "../x", "a;b"}) {
    INFO(bad);
    CHECK_FALSE(cppNamespaceRefusal(bad).empty());
  }
  auto r = test::runCli("compile --explain --no-cache " + test::materialPath("velvet_green.json") +
                        " --namespace 'materials; int x'");
  INFO(r.output);
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::StartsWith("--namespace: error[E-INVALID-NAME]: 'materials; int x' is not a C++"));
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
}

TEST_CASE("parameter values and ranges beyond fp32 are located E-PARAM-RANGE in both forms", "[names]") {
  const std::string head = R"({
  "name": "big",
  "model": "standard",
  "bricks": {"roughness": "roughness_clamped", "diffuse": "diffuse_lambert", "specular_d": "d_ggx", "specular_v": "v_smith_ggx_correlated", "fresnel": "f_schlick"},
  "surface": {"glsl": "void surface(inout MaterialInputs m, MaterialParams p) {}"},
  "parameters": {
)";
  struct Case {
    const char* what;
    const char* param;         // the parameter's object
    std::vector<int> columns;  // of each E-PARAM-RANGE on line 7
  };
  const std::vector<Case> cases = {
      {"a range reaching beyond fp32", R"({"type": "float", "default": 1, "range": [0, 1e39]})", {54}},
      {"a default and a range beyond fp32, each at its number",
       R"({"type": "float", "default": 1e39, "range": [0, 1e39]})",
       {42, 57}},
      {"a default beyond fp32, without a range", R"({"type": "float", "default": -1e39})", {42}},
      {"the largest float is still a float",
       R"({"type": "float", "default": 1, "range": [0, 3.4028234663852886e38]})",
       {}},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    auto ds = errorsOfJson(head + "    \"gain\": " + c.param + "\n  }\n}");
    REQUIRE(ds.size() == c.columns.size());
    for (size_t i = 0; i < ds.size(); ++i) {
      CHECK(ds[i].code == "E-PARAM-RANGE");
      CHECK(ds[i].where.line == 7);
      CHECK(ds[i].where.column == c.columns[i]);
      CHECK_THAT(ds[i].message, Catch::Contains("beyond the fp32 range"));
    }
  }
  SECTION("macro form") {
    auto ds = errorsOfMacro(
        "#define MATERIAL big\n#define MODEL standard\n#define BRICK_roughness roughness_clamped\n#define "
        "BRICK_diffuse diffuse_lambert\n#define BRICK_specular_d d_ggx\n#define BRICK_specular_v "
        "v_smith_ggx_correlated\n#define BRICK_fresnel f_schlick\n#define PARAM_gain 1e39 RANGE(0.0, 1e39)\n"
        "void surface(inout MaterialInputs m, MaterialParams p) {}\n");
    REQUIRE(ds.size() == 2);
    for (const auto& d : ds) {
      CHECK(d.code == "E-PARAM-RANGE");
      CHECK(d.where.line == 8);
      CHECK(d.where.column > 1);
      CHECK_THAT(d.message, Catch::Contains("beyond the fp32 range"));
    }
  }
}

TEST_CASE("a material path with a newline compiles: comments and #line carry it on one line", "[names]") {
  fs::path dir = test::freshTempDir("names", "newline");
  // The macro form: its surface code's #line names the material file itself.
  const fs::path file = dir / "worn\npaint\".mat";
  fs::copy_file(test::materialPath("worn_car_paint.mat"), file);
  std::vector<MaterialDesc> ms = loadMaterialFile(file.string(), test::shippedLibrary());
  REQUIRE(ms.size() == 1);
  for (Permutation perm : validationPermutationsFor(ms[0], test::shippedLibrary())) {
    EmittedShader s = emitPermutation(test::shippedLibrary(), perm);
    INFO(s.key);
    CHECK_NOTHROW(compileComputeGlsl(s.glsl, s.fileName, {ShaderStage::Compute, OptimizationLevel::O0, false}));
    CHECK_THAT(s.glsl, Catch::Contains("worn\\x0apaint\\x22.mat"));
  }
  auto r = test::runCli("compile -q --no-cache '" + file.string() + "' -o '" + (dir / "pkg").string() + "'");
  INFO(r.output);
  CHECK(r.exitCode == 0);
  fs::remove_all(dir);
}
