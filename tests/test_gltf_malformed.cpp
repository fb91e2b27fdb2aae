// Malformed glTF and .glb input (docs/gltf.md "Errors"): every case gives its diagnostic code
// at the position that causes it, and no input crashes the import. The table of cases is
// also what docs/gltf.md lists (`mb_tests "[.gltf-table]"` prints it).
#include <catch2/catch.hpp>

#include <iostream>

#include "load/gltf_container.hpp"
#include "support/gltf_support.hpp"

using namespace mb;

namespace {

struct BadCase {
  std::string name;
  std::string text;
  std::string code;
  std::string needle;  // where the diagnostic must point: first occurrence of this text ...
  std::string after;   // ... after this text (optional)
};

const std::string kAsset = R"({"asset": {"version": "2.0"}, )";

std::vector<BadCase> badJsonCases() {
  return {
      {"JSON syntax error", "{\"asset\": {\"version\": \"2.0\"},\n \"materials\": [}\n", "E-JSON-SYNTAX", "}", "["},
      {"document is not an object", "[1, 2]", "E-FIELD-TYPE", "[", ""},
      {"missing asset", R"({"materials": []})", "E-MISSING-FIELD", "{", ""},
      {"asset without version", R"({"asset": {"generator": "x"}})", "E-MISSING-FIELD", "{\"generator", ""},
      {"glTF 1.0", R"({"asset": {"version": "1.0"}})", "E-GLTF-VERSION", "\"1.0\"", ""},
      {"minVersion above 2.0", R"({"asset": {"version": "2.1", "minVersion": "2.1"}})", "E-GLTF-VERSION", "\"2.1\"",
       "minVersion"},
      {"version is a number", R"({"asset": {"version": 2}})", "E-FIELD-TYPE", "2", "version"},
      {"materials is an object", kAsset + R"("materials": {"a": 1}})", "E-FIELD-TYPE", "{", "materials"},
      {"material is a string", kAsset + R"("materials": ["gold"]})", "E-FIELD-TYPE", "\"gold\"", ""},
      {"factor of the wrong type", kAsset + R"("materials": [{"pbrMetallicRoughness": {"metallicFactor": "high"}}]})",
       "E-FIELD-TYPE", "\"high\"", ""},
      {"baseColorFactor with 3 numbers",
       kAsset + R"("materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0]}}]})", "E-FIELD-TYPE", "[1",
       ""},
      {"texture index out of range", kAsset + R"("textures": [{}], "materials": [{"normalTexture": {"index": 1}}]})",
       "E-GLTF-INDEX", "1}", "index"},
      {"texture index negative", kAsset + R"("textures": [{}], "materials": [{"occlusionTexture": {"index": -1}}]})",
       "E-FIELD-TYPE", "-1", ""},
      {"texture index not an integer",
       kAsset + R"("textures": [{}], "materials": [{"emissiveTexture": {"index": 0.5}}]})", "E-FIELD-TYPE", "0.5", ""},
      {"texture reference without index",
       kAsset + R"("textures": [{}], "materials": [{"emissiveTexture": {"texCoord": 0}}]})", "E-MISSING-FIELD",
       "{\"texCoord", ""},
      {"texture reference to a missing textures array",
       kAsset + R"("materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]})", "E-GLTF-INDEX", "0}",
       "index"},
      {"image index out of range",
       kAsset + R"("images": [], "textures": [{"source": 2}], "materials": [{"normalTexture": {"index": 0}}]})",
       "E-GLTF-INDEX", "2}", "source"},
      {"unknown alphaMode", kAsset + R"("materials": [{"alphaMode": "BLENDED"}]})", "E-FIELD-TYPE", "\"BLENDED\"", ""},
      {"ior below 1", kAsset + R"("materials": [{"extensions": {"KHR_materials_ior": {"ior": 0.5}}}]})",
       "E-PARAM-RANGE", "0.5", ""},
      {"extension object of the wrong type",
       kAsset + R"("materials": [{"extensions": {"KHR_materials_sheen": true}}]})", "E-FIELD-TYPE", "true", ""},
      {"extensionsUsed is not a list of strings", kAsset + R"("extensionsUsed": ["KHR_materials_sheen", 3]})",
       "E-FIELD-TYPE", "3", "extensionsUsed"},
      {"required extension not supported", kAsset + R"("extensionsRequired": ["KHR_materials_transmission"]})",
       "E-GLTF-REQUIRED-EXTENSION", "\"KHR_materials_transmission", ""},
  };
}

// A valid one-material .glb, and its parts, for the binary cases.
const std::string kJson = kAsset + R"("materials": [{"name": "m"}]})";

std::string withU32(std::string bytes, size_t offset, uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return bytes;
}

struct BadGlb {
  std::string name;
  std::string bytes;
  std::string code;
  int column;  // byte offset + 1 (line 1)
};

std::vector<BadGlb> badGlbCases() {
  std::string glb = packGlb(kJson);
  size_t jsonLength = glb.size() - 20;
  std::string withBin = packGlb(kJson, "abcd");
  return {
      {"empty .glb", "", "E-GLB-TRUNCATED", 1},
      {"header shorter than 12 bytes", glb.substr(0, 8), "E-GLB-TRUNCATED", 9},
      {"wrong magic ('gLTf')", withU32(glb, 0, 0x66544C67), "E-GLB-HEADER", 1},
      {"container version 1", withU32(glb, 4, 1), "E-GLB-HEADER", 5},
      {"truncated file (header length > size)", glb.substr(0, glb.size() - 4), "E-GLB-TRUNCATED",
       static_cast<int>(glb.size() - 4 + 1)},
      {"header length < size", glb + std::string(4, ' '), "E-GLB-HEADER", 9},
      {"no chunk after the header", withU32(glb.substr(0, 12), 8, 12), "E-GLB-TRUNCATED", 13},
      {"chunk header cut short", withU32(glb.substr(0, 16), 8, 16), "E-GLB-TRUNCATED", 13},
      {"chunk length beyond the file", withU32(glb, 12, static_cast<uint32_t>(jsonLength + 4)), "E-GLB-CHUNK", 13},
      {"chunk length not a multiple of 4",
       withU32(withU32(glb, 12, static_cast<uint32_t>(jsonLength - 2)), 8, static_cast<uint32_t>(glb.size() - 2))
           .substr(0, glb.size() - 2),
       "E-GLB-CHUNK", 13},
      {"first chunk is BIN", withU32(glb, 16, 0x004E4942), "E-GLB-CHUNK", 17},
      {"two JSON chunks", withU32(withBin, 20 + jsonLength + 4, 0x4E4F534A), "E-GLB-CHUNK",
       static_cast<int>(20 + jsonLength + 4 + 1)},
  };
}

}  // namespace

TEST_CASE("malformed glTF JSON: each case has its code at its position", "[gltf]") {
  for (const auto& c : badJsonCases()) {
    SECTION(c.name) {
      std::vector<Diagnostic> ds = test::gltfDiagnostics(c.text);
      Diagnostic d = test::theOne(ds, c.code);
      CHECK(d.where.file == "t.gltf");
      test::requireAt(d, test::positionOf(c.text, c.needle, c.after));
    }
  }
}

TEST_CASE("malformed .glb: each case has its code at its byte offset", "[gltf]") {
  for (const auto& c : badGlbCases()) {
    SECTION(c.name) {
      std::vector<Diagnostic> ds = test::gltfDiagnostics(c.bytes, "t.glb");
      Diagnostic d = test::theOne(ds, c.code);
      INFO(formatDiagnostic(d));
      CHECK(d.where.line == 1);
      CHECK(d.where.column == c.column);
      CHECK_THAT(d.message, Catch::Matchers::Contains("at byte " + std::to_string(c.column - 1)));
    }
  }
  SECTION("a JSON error inside a .glb is at line:column of the JSON chunk") {
    std::string json = "{\"asset\": {\"version\": \"2.0\"},\n  \"materials\": [,]}";
    Diagnostic d = test::theOne(test::gltfDiagnostics(packGlb(json), "t.glb"), "E-JSON-SYNTAX");
    test::requireAt(d, test::positionOf(json, ",", "["));
  }
}

TEST_CASE("several errors in one glTF are all reported, in file order", "[gltf]") {
  std::string text = kAsset + R"("textures": [{}], "materials": [
    {"pbrMetallicRoughness": {"roughnessFactor": "rough", "baseColorTexture": {"index": 7}}},
    {"alphaMode": "blend", "extensions": {"KHR_materials_ior": {"ior": -2}}}]})";
  std::vector<Diagnostic> ds = test::gltfDiagnostics(text);
  std::vector<std::string> codes;
  for (const auto& d : ds) codes.push_back(d.code);
  CHECK(codes == std::vector<std::string>{"E-FIELD-TYPE", "E-GLTF-INDEX", "E-FIELD-TYPE", "E-PARAM-RANGE"});
  for (size_t i = 1; i < ds.size(); ++i)
    CHECK(std::make_pair(ds[i - 1].where.line, ds[i - 1].where.column) <
          std::make_pair(ds[i].where.line, ds[i].where.column));
  CHECK(ds[2].suggestion == "did you mean 'BLEND'?");
}

TEST_CASE("no prefix or byte flip of a valid .glb or .gltf crashes the import", "[gltf]") {
  std::string rich = kAsset + R"("textures": [{"source": 0}], "images": [{"uri": "a.png"}],
  "materials": [{"name": "x", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
    "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}}]})";
  std::string glb = packGlb(rich, "bin!");
  size_t failures = 0;
  auto attempt = [&](const std::string& bytes) {
    try {
      parseGltf(bytes, "t.glb", test::shippedLibrary());
    } catch (const DiagnosticError& e) {
      ++failures;
      REQUIRE_FALSE(e.diagnostics().empty());
    }
  };
  for (size_t n = 0; n < glb.size(); ++n) attempt(glb.substr(0, n));
  for (size_t n = 0; n < rich.size(); ++n) attempt(rich.substr(0, n));
  // Every prefix is invalid: a shorter .glb disagrees with its header, a shorter .gltf is
  // unterminated JSON.
  CHECK(failures == glb.size() + rich.size());
  for (size_t i = 0; i < 28; ++i)
    for (unsigned char bit : {0x01, 0x80}) {
      std::string flipped = glb;
      flipped[i] = static_cast<char>(flipped[i] ^ bit);
      attempt(flipped);
    }
  CHECK_NOTHROW(parseGltf(glb, "t.glb", test::shippedLibrary()));
}

TEST_CASE("a missing file is E-FILE-NOT-FOUND; a directory or a device E-FILE-NOT-REGULAR, without hanging", "[gltf]") {
  test::theOne(test::diagnosticsOf([&] { readGltf("/nonexistent/scene.gltf", test::shippedLibrary()); }),
               "E-FILE-NOT-FOUND");
  for (const char* path : {"/tmp", "/dev/zero"}) {
    INFO(path);
    test::theOne(test::diagnosticsOf([&] { readGltf(path, test::shippedLibrary()); }), "E-FILE-NOT-REGULAR");
  }
}

// Prints the markdown table of docs/gltf.md "Errors": every bad-input case and its message.
TEST_CASE("print the table of malformed glTF cases", "[.gltf-table]") {
  std::cout << "| case | diagnostic |\n|---|---|\n";
  auto row = [](const std::string& name, const std::string& bytes, const std::string& file) {
    std::vector<Diagnostic> ds = test::gltfDiagnostics(bytes, file);
    std::string msg = ds.empty() ? "(none)" : formatDiagnostic(ds.front());
    for (size_t i = 1; i < ds.size(); ++i) msg += "<br>" + formatDiagnostic(ds[i]);
    std::string escaped;
    for (char ch : msg) escaped += ch == '|' ? std::string("\\|") : std::string(1, ch);
    std::cout << "| " << name << " | `" << escaped << "` |\n";
  };
  for (const auto& c : badJsonCases()) row(c.name, c.text, "t.gltf");
  for (const auto& c : badGlbCases()) row(c.name + " (.glb)", c.bytes, "t.glb");
}
