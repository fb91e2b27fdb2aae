// Brick facts as data (docs/architecture.md "Adding a brick"): the facts the compiler acts on
// by brick (fp16 twin, energy lobe, half-vector map and theory) are read from the brick's
// manifest entry, checked with file:line:column errors, and a new D brick added to a scratch
// copy of the library with three files (GLSL, reference, manifest entry: tests/data/
// new_d_brick/) is compiled, validated, stressed, integrated by the energy checks and listed
// in the catalogue, with no change to compiler/.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "emit/precision.hpp"
#include "energy/energy_checks.hpp"
#include "fake_library.hpp"
#include "load/gltf_import.hpp"
#include "lut/lut_kernel.hpp"
#include "preview/preview.hpp"
#include "stress/stress_run.hpp"
#include "support/gltf_support.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/brick_catalogue.hpp"
#include "validate/precision_domain.hpp"
#include "validate/validation.hpp"

using namespace mb;
using mb::test::FakeLibrary;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

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

// Fake specular_d with an energy role and its bricks' entries (none where empty), and a
// visibility slot with one V.
std::map<std::string, std::string> energyLibrary(const std::string& ggxEnergy, const std::string& beckmannEnergy) {
  std::string d = fakeSlotD("\"bricks\": [", "\"energy\": \"distribution\",\n  \"bricks\": [");
  d.replace(d.find("\"geometry\""), 0, "\"energy\": " + ggxEnergy + ",\n      ");
  if (!beckmannEnergy.empty())
    d.replace(d.find("\"notes\": \"test brick\""), 0, "\"energy\": " + beckmannEnergy + ",\n      ");
  std::string v = R"json({
  "name": "specular_v",
  "description": "V",
  "returns": "float",
  "params": [{"name": "g", "type": "Geometry"}, {"name": "alpha", "type": "float"}],
  "energy": "visibility",
  "bricks": [
    {
      "id": "v_smith",
      "name": "Smith",
      "function": "mb_v_smith",
      "file": "v_smith.glsl",
      "citation": "Heitz 2014",
      "requires": ["common"],
      "domain": {"alpha": [0.002, 1.0]},
      "tolerance": {"abs": 0.0, "rel": 1e-6, "reason": "sqrt"},
      "energy": {"lobe": "specular", "expectation": "conserving", "note": "G2 <= G1(v)"}
    }
  ]
}
)json";
  std::string manifest = test::fakeLibraryFiles().at("manifest.json");
  manifest.replace(manifest.find("\"fresnel\"]"), 10, "\"fresnel\", \"specular_v\"]");
  return {{"manifest.json", manifest},
          {"specular_d/slot.json", d},
          {"specular_v/slot.json", v},
          {"specular_v/v_smith.glsl", "float mb_v_smith(Geometry g, float alpha) { return alpha; }\n"}};
}

const char* kGgxEnergy = R"({"lobe": "specular", "half_vector_map": "ggx", "visibility": "all"})";
const char* kBeckmannEnergy = R"({"lobe": "specular", "half_vector_map": "beckmann", "visibility": ["v_smith"]})";

// A copy of the shipped library in a fresh temporary folder, removed on destruction.
class ScratchLibrary {
 public:
  ScratchLibrary() {
    static std::atomic<int> counter{0};
    root_ = fs::temp_directory_path() /
            ("mb_scratch_lib_" + std::to_string(std::random_device{}()) + "_" + std::to_string(counter++));
    fs::copy(ShaderLibrary::defaultRoot(), root_, fs::copy_options::recursive);
  }
  ~ScratchLibrary() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  ScratchLibrary(const ScratchLibrary&) = delete;
  ScratchLibrary& operator=(const ScratchLibrary&) = delete;
  const fs::path& root() const { return root_; }

  // Adds a brick to `slot`: its GLSL file beside the slot.json, its entry appended there.
  void addBrick(const std::string& slot, const fs::path& glsl, const fs::path& entryFile) const {
    fs::copy_file(glsl, root_ / slot / glsl.filename());
    auto doc = nlohmann::ordered_json::parse(test::readFile(root_ / slot / "slot.json"));
    doc["bricks"].push_back(nlohmann::ordered_json::parse(test::readFile(entryFile)));
    std::ofstream(root_ / slot / "slot.json", std::ios::binary) << doc.dump(2) << "\n";
  }
  // Replaces the first `from` in the library file `relative` by `to`; returns the new text.
  std::string edit(const std::string& relative, const std::string& from, const std::string& to) const {
    std::string text = test::readFile(root_ / relative);
    auto pos = text.find(from);
    REQUIRE(pos != std::string::npos);
    text.replace(pos, from.size(), to);
    std::ofstream(root_ / relative, std::ios::binary) << text;
    return text;
  }
  // Keeps only these slots, and no models (nor the glTF defaults, which name one), in
  // manifest.json (a smaller catalogue).
  void keepSlots(const std::vector<std::string>& slots) const {
    auto doc = nlohmann::ordered_json::parse(test::readFile(root_ / "manifest.json"));
    doc["slots"] = slots;
    doc["models"] = nlohmann::ordered_json::array();
    doc.erase("gltf_defaults");
    std::ofstream(root_ / "manifest.json", std::ios::binary) << doc.dump(2) << "\n";
  }

 private:
  fs::path root_;
};

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

TEST_CASE("energy: each brick of an energy slot declares its lobe, checked at file:line:column",
          "[library][brick-data]") {
  SECTION("valid entries load") {
    FakeLibrary files(energyLibrary(kGgxEnergy, kBeckmannEnergy));
    auto lib = ShaderLibrary::load(files.root());
    CHECK(lib.findSlot("specular_d")->energyRole == "distribution");
    const BrickEnergy& e = lib.findBrick("d_beckmann")->energy;
    CHECK(e.lobe == "specular");
    CHECK(e.halfVectorMap == "beckmann");
    CHECK_FALSE(e.allVisibilities);
    CHECK(e.visibilities == std::vector<std::string>{"v_smith"});
    CHECK(lib.findBrick("v_smith")->energy.expectation == "conserving");
    // Both D bricks pair with the one V: two lobes, GGX first (map order), no C++ table.
    auto lobes = energy::energyLobes(lib);
    REQUIRE(lobes.size() == 2);
    CHECK(lobes[0].name == "d_ggx * v_smith");
    CHECK(lobes[1].name == "d_beckmann * v_smith");
    CHECK(lobes[1].map == energy::HalfVectorMapKind::Beckmann);
    CHECK(lobes[1].expectation == energy::Expectation::Conserving);
    CHECK(lobes[1].note == "G2 <= G1(v)");
  }
  SECTION("a D brick without an entry fails: it would be silently left out") {
    FakeLibrary lib(energyLibrary(kGgxEnergy, ""));
    auto d = onlyError(lib, "E-MISSING-FIELD", 20, 5);
    CHECK_THAT(d.message, Contains("brick 'd_beckmann' needs an 'energy' entry"));
  }
  SECTION("an unknown half-vector map") {
    FakeLibrary lib(
        energyLibrary(R"({"lobe": "specular", "half_vector_map": "gxx", "visibility": "all"})", kBeckmannEnergy));
    auto d = onlyError(lib, "E-INVALID-VALUE", 16, 57);
    CHECK_THAT(d.message, Contains("expected one of 'ggx', 'beckmann', 'charlie', 'ashikhmin'"));
    CHECK(d.suggestion == "did you mean 'ggx'?");
  }
  SECTION("a listed V that is not a V brick of the lobe") {
    FakeLibrary lib(
        energyLibrary(kGgxEnergy, R"({"lobe": "sheen", "half_vector_map": "beckmann", "visibility": ["v_smith"]})"));
    auto d = onlyError(lib, "E-UNKNOWN-BRICK", 29, 81);
    CHECK_THAT(d.message, Contains("names 'v_smith', which is not a V brick of the 'sheen' lobe"));
  }
}

TEST_CASE("the shipped library's energy facts keep every lobe of the C++ tables they replace", "[energy][brick-data]") {
  auto lobes = energy::energyLobes(test::shippedLibrary());
  std::vector<std::string> names;
  for (const auto& l : lobes) names.push_back(l.name);
  // The order and pairing of docs/energy.md.
  CHECK(names == std::vector<std::string>{"d_ggx * v_smith_ggx_correlated",
                                          "d_ggx * v_schlick_ggx_ue4",
                                          "d_ggx * v_smith_ggx_correlated_fast",
                                          "d_ggx * v_schlick_ggx_ibl",
                                          "d_ggx * v_kelemen",
                                          "d_ggx * v_smith_ggx_separable",
                                          "d_ggx * v_implicit",
                                          "d_ggx * v_neumann",
                                          "d_ggx * v_cook_torrance",
                                          "d_beckmann * v_cook_torrance",
                                          "d_charlie * v_ashikhmin",
                                          "d_charlie * v_charlie",
                                          "d_charlie * v_charlie_no_softening",
                                          "d_ashikhmin * v_ashikhmin",
                                          "d_ggx_aniso * v_smith_ggx_correlated_aniso",
                                          "d_ggx_aniso * v_smith_ggx_separable_aniso",
                                          "diffuse_lambert",
                                          "diffuse_disney_renormalized",
                                          "diffuse_activision_multiscatter",
                                          "diffuse_fabric_lambert",
                                          "diffuse_disney_burley"});
  for (const auto& l : lobes) {
    INFO(l.name);
    CHECK_FALSE(l.note.empty());
  }
}

TEST_CASE("the lobe the multiscatter compensation is checked on is found by its facts, not its name",
          "[energy][brick-data]") {
  // Shipped: the isotropic GGX lobe with the dfg_visibility brick.
  const ShaderLibrary& shipped = test::shippedLibrary();
  auto lobes = energy::energyLobes(shipped);
  const energy::Lobe* dfg = energy::dfgLobe(lobes, shipped);
  REQUIRE(dfg);
  CHECK(dfg->name == "d_ggx * v_smith_ggx_correlated");
  // A library where no V takes the role has none (the checks then skip the compensation).
  FakeLibrary files(energyLibrary(kGgxEnergy, kBeckmannEnergy));
  auto fake = ShaderLibrary::load(files.root());
  CHECK(energy::dfgLobe(energy::energyLobes(fake), fake) == nullptr);
}

TEST_CASE("truth_note: read from the brick entry, an empty one fails at file:line:column", "[library][brick-data]") {
  const std::string geometry = "\"geometry\": {\"NoV\": [0.01, 1.0]},";
  SECTION("declared") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD(geometry, geometry + "\n      \"truth_note\": \"truth at alpha = 1\",")}});
    CHECK(ShaderLibrary::load(files.root()).findBrick("d_ggx")->truthNote == "truth at alpha = 1");
  }
  SECTION("empty") {
    FakeLibrary files({{"specular_d/slot.json", fakeSlotD(geometry, geometry + "\n      \"truth_note\": \"\",")}});
    auto d = onlyError(files, "E-EMPTY-FIELD", 16, 21);
    CHECK_THAT(d.message, Contains("truth_note"));
  }
  // The shipped brick that assumes f0 = 0.04; bench prints it beside the brick.
  CHECK(test::shippedLibrary().findBrick("env_brdf_approx_nonmetal")->truthNote == "truth at f0 = 0.04");
  CHECK(test::shippedLibrary().findBrick("env_brdf_approx")->truthNote.empty());
}

TEST_CASE("roughness: an input's kind is read from its declaration, checked at file:line:column",
          "[library][brick-data][precision]") {
  const std::string alpha = R"({"name": "alpha", "type": "float"})";
  SECTION("a new input name declared a roughness gets the fp16 floor, with no C++ list of names") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD(alpha, R"({"name": "alpha", "type": "float", "roughness": "alpha"})")}});
    auto lib = ShaderLibrary::load(files.root());
    CHECK(lib.findSlot("specular_d")->params[1].roughness == RoughnessKind::Alpha);
    CHECK(lib.roughnessKind("alpha") == RoughnessKind::Alpha);
    CHECK(lib.roughnessKind("f0") == RoughnessKind::None);
    SampleDomain declared{{{"alpha", {0.0, 1.0}}, {"f0", {0.0, 1.0}}}, {}, {}};
    SampleDomain half = domainAtPrecision(lib, declared, ShaderPrecision::Fp16);
    CHECK(half.ranges.at("alpha").lo == minAlpha(ShaderPrecision::Fp16));
    CHECK(half.ranges.at("f0").lo == 0.0);
    CHECK(domainAtPrecision(lib, declared, ShaderPrecision::Fp32).ranges.at("alpha").lo == 0.0);
  }
  SECTION("undeclared, the same name is no roughness") {
    auto lib = ShaderLibrary::load(FakeLibrary().root());
    CHECK(lib.roughnessKind("alpha") == RoughnessKind::None);
    SampleDomain half = domainAtPrecision(lib, {{{"alpha", {0.0, 1.0}}}, {}, {}}, ShaderPrecision::Fp16);
    CHECK(half.ranges.at("alpha").lo == 0.0);
  }
  SECTION("an unknown kind") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD(alpha, R"({"name": "alpha", "type": "float", "roughness": "alfa"})")}});
    auto d = onlyError(files, "E-INVALID-VALUE", 5, 97);
    CHECK_THAT(d.message, Contains("expected one of 'perceptual', 'alpha'"));
    CHECK(d.suggestion == "did you mean 'alpha'?");
  }
  SECTION("a vector input cannot be a roughness") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD(alpha, R"({"name": "alpha", "type": "vec2", "roughness": "alpha"})")}});
    auto d = onlyError(files, "E-INVALID-VALUE", 5, 96);
    CHECK_THAT(d.message, Contains("only a float input is a roughness"));
  }
  SECTION("inputs of one name disagree: probes look inputs up by name") {
    // The energy library's V slot has an undeclared "alpha" beside the D slot's declared one.
    auto files = energyLibrary(kGgxEnergy, kBeckmannEnergy);
    std::string& d = files.at("specular_d/slot.json");
    d.replace(d.find(alpha), alpha.size(), R"({"name": "alpha", "type": "float", "roughness": "alpha"})");
    FakeLibrary lib(files);
    auto ds = loadErrors(lib);
    INFO("diagnostics:\n" << (ds.empty() ? std::string("(none)") : DiagnosticError(ds).what()));
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == "E-INVALID-VALUE");
    CHECK(ds[0].where.file == lib.path("specular_v/slot.json"));
    CHECK(ds[0].where.line == 5);
    CHECK(ds[0].where.column == 49);
    CHECK_THAT(ds[0].message, Contains("input 'alpha' has no \"roughness\", but the input of that name at " +
                                       lib.path("specular_d/slot.json") + ":5:"));
  }
}

TEST_CASE("the shipped library's roughness inputs are the names the C++ list had", "[library][brick-data][precision]") {
  const auto& kinds = test::shippedLibrary().roughnessKinds();
  CHECK(kinds == std::map<std::string, RoughnessKind>{{"ab", RoughnessKind::Alpha},
                                                      {"alpha", RoughnessKind::Alpha},
                                                      {"at", RoughnessKind::Alpha},
                                                      {"perceptualRoughness", RoughnessKind::Perceptual},
                                                      {"roughness", RoughnessKind::Perceptual}});
}

TEST_CASE("kernel_roles: the LUT and prefilter kernels find their bricks by role", "[library][brick-data][lut]") {
  const std::string ggxEnd = "\"geometry\": {\"NoV\": [0.01, 1.0]},";
  const std::string beckmannEnd = "\"notes\": \"test brick\"";
  auto roles = [](const std::string& role) { return "\n      \"kernel_roles\": [\"" + role + "\"],"; };
  SECTION("a brick declaring a role takes it, with no C++ change") {
    FakeLibrary files(
        {{"specular_d/slot.json", fakeSlotD(beckmannEnd, roles("prefilter_d") + "\n      " + beckmannEnd)}});
    auto lib = ShaderLibrary::load(files.root());
    REQUIRE(lib.brickForKernelRole("prefilter_d") != nullptr);
    CHECK(lib.brickForKernelRole("prefilter_d")->id == "d_beckmann");
    CHECK(lib.brickForKernelRole("cloth_dfg_d") == nullptr);
  }
  SECTION("without the roles, the LUT kernel names the one it misses") {
    try {
      lut::lutBricks(ShaderLibrary::load(FakeLibrary().root()));
      FAIL("no error");
    } catch (const DiagnosticError& e) {
      REQUIRE(e.diagnostics().size() == 1);
      CHECK(e.diagnostics()[0].code == "E-UNKNOWN-BRICK");
      CHECK_THAT(e.diagnostics()[0].message, Contains("needs a brick with kernel role 'hammersley'"));
    }
  }
  SECTION("an unknown role") {
    FakeLibrary files({{"specular_d/slot.json", fakeSlotD(ggxEnd, ggxEnd + roles("prefilter_dd"))}});
    auto d = onlyError(files, "E-INVALID-VALUE", 16, 24);
    CHECK(d.suggestion == "did you mean 'prefilter_d'?");
  }
  SECTION("a role of another slot: the kernel calls that slot's signature") {
    FakeLibrary files({{"specular_d/slot.json", fakeSlotD(ggxEnd, ggxEnd + roles("dfg_visibility"))}});
    auto d = onlyError(files, "E-INVALID-VALUE", 16, 24);
    CHECK_THAT(d.message, Contains("kernel role 'dfg_visibility' is for a brick of slot 'specular_v'"));
  }
  SECTION("a role taken twice") {
    std::string text = fakeSlotD(ggxEnd, ggxEnd + roles("prefilter_d"));
    text.replace(text.find(beckmannEnd), 0, "\"kernel_roles\": [\"prefilter_d\"],\n      ");
    FakeLibrary files({{"specular_d/slot.json", text}});
    auto d = onlyError(files, "E-DUPLICATE-NAME", 28, 24);
    CHECK_THAT(d.message, Contains("kernel role 'prefilter_d' is already taken by brick 'd_ggx' at "));
  }
}

TEST_CASE("the shipped library's kernel roles are the bricks the C++ named", "[library][brick-data][lut]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  CHECK(lut::lutBricks(lib).all() == std::vector<std::string>{"hammersley_bitreverse", "importance_sample_ggx",
                                                              "v_smith_ggx_correlated", "d_charlie", "v_ashikhmin"});
  REQUIRE(lib.brickForKernelRole("prefilter_d") != nullptr);
  CHECK(lib.brickForKernelRole("prefilter_d")->id == "d_ggx");
  REQUIRE(lib.brickForKernelRole("multiscatter") != nullptr);
  CHECK(lib.brickForKernelRole("multiscatter")->id == "energy_compensation_filament");
  REQUIRE(lib.brickForKernelRole("preview_tonemap") != nullptr);
  CHECK(lib.brickForKernelRole("preview_tonemap")->id == "tonemap_aces_narkowicz");
}

TEST_CASE("the preview's default tonemap is the brick with kernel role preview_tonemap",
          "[library][brick-data][preview]") {
  ScratchLibrary scratch;
  const std::string role = "\"kernel_roles\": [\"preview_tonemap\"],\n      ";
  scratch.edit("tonemap/slot.json", role, "");
  SECTION("moved to another tonemap brick: taken there, with no C++ change") {
    scratch.edit("tonemap/slot.json", "\"file\": \"tonemap_aces_hill.glsl\",",
                 role + "\"file\": \"tonemap_aces_hill.glsl\",");
    auto lib = ShaderLibrary::load(scratch.root());
    REQUIRE(lib.brickForKernelRole("preview_tonemap") != nullptr);
    CHECK(lib.brickForKernelRole("preview_tonemap")->id == "tonemap_aces_hill");
    CHECK_NOTHROW(preview::checkPreviewOptions(lib, {}, preview::PreviewOptions{}));
  }
  SECTION("taken by no brick: the preview needs --tonemap, and says so") {
    auto lib = ShaderLibrary::load(scratch.root());
    auto ds = test::diagnosticsOf([&] { preview::checkPreviewOptions(lib, {}, preview::PreviewOptions{}); });
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == "E-PREVIEW-TONEMAP");
    CHECK_THAT(ds[0].message, Contains("kernel role 'preview_tonemap'"));
    preview::PreviewOptions named;
    named.tonemap = "tonemap_aces_hill";
    CHECK_NOTHROW(preview::checkPreviewOptions(lib, {}, named));
  }
}

namespace {

// A glTF material with the sheen and anisotropy extensions, for the glTF defaults below.
const char* kSheenGltf = R"({"asset": {"version": "2.0"}, "materials": [{"name": "Velvet", "extensions": {
  "KHR_materials_sheen": {"sheenColorFactor": [0.5, 0.5, 0.5]},
  "KHR_materials_anisotropy": {"anisotropyStrength": 0.5}}}]})";

std::map<std::string, std::string> bricksOf(const MaterialSource& s) {
  std::map<std::string, std::string> out;
  for (const auto& [role, id] : s.bricks) out[role.value] = id.value;
  return out;
}

// The only diagnostic of loading `root`, with its code, at the first `needle` (after `after`)
// of gltf_defaults.json's `text`.
Diagnostic onlyGltfDefaultsError(const fs::path& root, const std::string& text, const std::string& code,
                                 const std::string& needle, const std::string& after = "") {
  std::vector<Diagnostic> ds;
  try {
    ShaderLibrary::load(root);
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  INFO("diagnostics:\n" << (ds.empty() ? std::string("(none)") : DiagnosticError(ds).what()));
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == code);
  CHECK(fs::path(ds[0].where.file) == (root / "gltf_defaults.json").lexically_normal());
  auto [line, column] = test::positionOf(text, needle, after);
  CHECK(ds[0].where.line == line);
  CHECK(ds[0].where.column == column);
  return ds[0];
}

}  // namespace

TEST_CASE("glTF defaults: read from the library's gltf_defaults.json, checked at file:line:column",
          "[library][brick-data][gltf]") {
  ScratchLibrary scratch;
  SECTION("a binding declared in the data is bound, with no C++ change") {
    scratch.edit("gltf_defaults.json", R"({"role": "diffuse", "brick": "diffuse_lambert"})",
                 R"({"role": "diffuse", "brick": "diffuse_disney_burley"})");
    scratch.edit(
        "gltf_defaults.json", "\"features\": [",
        R"("features": [{"feature": "sheen", "why": "test", "bricks": [{"role": "sheen_v", "brick": "v_charlie"}]},)");
    auto lib = ShaderLibrary::load(scratch.root());
    auto ms = parseGltf(kSheenGltf, "t.gltf", lib);
    REQUIRE(ms.size() == 1);
    auto bricks = bricksOf(ms[0].source);
    CHECK(bricks.at("diffuse") == "diffuse_disney_burley");
    CHECK(bricks.at("sheen_v") == "v_charlie");
    CHECK(bricks.at("anisotropy_alpha") == "aniso_alpha_gltf");
    MaterialDesc d = resolveMaterial(ms[0].source, lib);
    CHECK(d.bricks.at("sheen_v") == "v_charlie");
    CHECK(d.bricks.at("diffuse") == "diffuse_disney_burley");
  }
  // Each mistake in the file: what it replaces, the error, where, and what the message says.
  struct Mistake {
    const char* what;
    const char* from;
    const char* to;
    const char* code;
    const char* at;     // the error's position: the first occurrence, after `after`
    const char* after;  // (empty: from the start)
    const char* says;   // in the message or its suggestion
  };
  const Mistake mistakes[] = {
      {"a brick of another slot", "\"aniso_alpha_gltf\"", "\"d_ggx\"", "E-UNKNOWN-BRICK", "\"d_ggx\"",
       "anisotropy_alpha", "'d_ggx' is not a brick of slot 'anisotropy_alpha'"},
      {"an unknown brick id", "\"f_schlick_nov\"", "\"f_schlick_now\"", "E-UNKNOWN-BRICK", "\"f_schlick_now\"", "",
       "did you mean 'f_schlick_nov'"},
      {"an unknown role", "\"role\": \"fresnel\"", "\"role\": \"fresnell\"", "E-UNKNOWN-ROLE", "\"fresnell\"", "",
       "did you mean 'fresnel'?"},
      {"a feature's role in 'always': a role the material may not have",
       "\"role\": \"fresnel\", \"brick\": \"f_schlick\"", "\"role\": \"clearcoat_fresnel\", \"brick\": \"f_schlick\"",
       "E-INVALID-VALUE", "\"clearcoat_fresnel\"", "", "exists only with feature 'clearcoat'"},
      {"a feature the model does not have", "\"feature\": \"anisotropy\"", "\"feature\": \"anisotropic\"",
       "E-UNKNOWN-NAME", "\"anisotropic\"", "", "did you mean 'anisotropy'?"},
      {"a missing field", "\"model\": \"standard\",", "", "E-MISSING-FIELD", "{", "", "model"},
  };
  for (const Mistake& m : mistakes) {
    DYNAMIC_SECTION(m.what) {
      std::string text = scratch.edit("gltf_defaults.json", m.from, m.to);
      auto d = onlyGltfDefaultsError(scratch.root(), text, m.code, m.at, m.after);
      CHECK_THAT(d.message + " " + d.suggestion, Contains(m.says));
    }
  }
  SECTION("a library without glTF defaults loads, and refuses glTF import at its manifest") {
    scratch.edit("manifest.json", ",\n  \"gltf_defaults\": \"gltf_defaults.json\"", "");
    auto lib = ShaderLibrary::load(scratch.root());
    CHECK(lib.gltfDefaults().model.empty());
    auto ds = test::diagnosticsOf([&] { parseGltf(kSheenGltf, "t.gltf", lib); });
    REQUIRE(ds.size() == 1);
    CHECK(ds[0].code == "E-GLTF-NO-DEFAULTS");
    CHECK(fs::path(ds[0].where.file) == scratch.root() / "manifest.json");
    CHECK(ds[0].where.line == 1);
  }
}

TEST_CASE("the shipped glTF defaults are the bricks the C++ named", "[library][brick-data][gltf]") {
  const GltfDefaults& d = test::shippedLibrary().gltfDefaults();
  CHECK(d.file == "gltf_defaults.json");
  CHECK(d.model == "standard");
  auto pairs = [](const std::vector<GltfBinding>& v) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& b : v) out.emplace_back(b.role, b.brick);
    return out;
  };
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  CHECK(pairs(d.always) == Pairs{{"roughness", "roughness_clamped"},
                                 {"diffuse", "diffuse_lambert"},
                                 {"specular_d", "d_ggx"},
                                 {"specular_v", "v_smith_ggx_correlated"},
                                 {"fresnel", "f_schlick"}});
  REQUIRE(d.features.size() == 2);
  CHECK(pairs(d.features.at("clearcoat")) == Pairs{{"clearcoat_v", "v_smith_ggx_correlated"},
                                                   {"clearcoat_fresnel", "f_schlick_nov"},
                                                   {"f0_clearcoat", "f0_clearcoat_none"},
                                                   {"clearcoat_base_roughness", "coat_base_roughness_keep"}});
  CHECK(pairs(d.features.at("anisotropy")) == Pairs{{"anisotropy_alpha", "aniso_alpha_gltf"}});
}

TEST_CASE("a new D brick from three files joins validation, stress, energy and the catalogue", "[brick-data][vulkan]") {
  const fs::path data = test::sourceDir() / "tests/data/new_d_brick";
  ScratchLibrary scratch;
  scratch.addBrick("specular_d", data / "d_ggx_tan2.glsl", data / "entry.json");
  auto lib = ShaderLibrary::load(scratch.root());
  const Brick* brick = lib.findBrick("d_ggx_tan2");
  REQUIRE(brick != nullptr);
  REQUIRE(ref::Registry::references().find("d_ggx_tan2") != nullptr);
  harness::VulkanHarness gpu(harness::testDeviceOptions());

  // Compiled and validated against its reference, and stressed.
  ProbeProgram probe = buildBrickProbe(lib, *brick);
  ValidationRecord record = validateProbe(gpu, probe, "brick", 2048, 1);
  CHECK(record.passed());
  StressResult stress = stressProbe(gpu, probe, "brick", "d_ggx_tan2", {256, 1});
  CHECK(stress.passed());

  // In the energy checks, after the shipped lobes of its kind and map, and conserving there.
  auto lobes = energy::energyLobes(lib);
  auto it = std::find_if(lobes.begin(), lobes.end(),
                         [](const energy::Lobe& l) { return l.name == "d_ggx_tan2 * v_smith_ggx_correlated"; });
  REQUIRE(it != lobes.end());
  CHECK(it - lobes.begin() == 9);  // after the 9 lobes of d_ggx, before Beckmann's
  CHECK(lobes.size() == energy::energyLobes(test::shippedLibrary()).size() + 1);
  energy::ProbeCache probes(lib);
  auto furnace = energy::whiteFurnace(gpu, probes, {*it}, energy::EnergyGrid::coarse());
  REQUIRE(furnace.size() == 1);
  CHECK(furnace[0].gpuMatchesReference());
  CHECK_FALSE(furnace[0].exceedsOne());

  // In the catalogue (of the scratch library cut to the slots its lobe needs, to stay small).
  scratch.keepSlots({"specular_d", "specular_v"});
  auto small = ShaderLibrary::load(scratch.root());
  std::string catalogue = brickCatalogueMarkdown(small, gpu, {256, 1});
  CHECK_THAT(catalogue, Contains("`d_ggx_tan2` GGX / Trowbridge-Reitz (tan^2 form)"));
  CHECK(gpu.validationMessages().empty());
}
