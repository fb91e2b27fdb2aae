// Axes, validity, quality, folding and planning (docs/scenes.md), and `matbricks verify`.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "emit/emitter.hpp"
#include "load/scene_desc.hpp"
#include "permute/axes.hpp"
#include "permute/scene_plan.hpp"
#include "permute/specialize.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

const ShadingModel& model(const std::string& name) { return *test::shippedLibrary().findModel(name); }

MaterialDesc material(const std::string& name) { return test::shippedMaterial(name); }

MaterialUse use(std::map<std::string, std::vector<double>> values) { return test::useWith(std::move(values)); }

SceneDesc exampleScene(const std::string& file) {
  return loadScene((test::sourceDir() / "examples/scenes" / file).string(), test::shippedLibrary());
}

std::vector<std::string> keysOf(const ScenePlan& plan) {
  std::vector<std::string> keys;
  for (const auto& p : plan.required) keys.push_back(p.key());
  return keys;
}

// Every subset of `all`, for the brute-force count.
template <class T>
std::vector<std::vector<T>> subsets(const std::vector<T>& all) {
  std::vector<std::vector<T>> out;
  for (size_t mask = 0; mask < (size_t{1} << all.size()); ++mask) {
    std::vector<T> s;
    for (size_t i = 0; i < all.size(); ++i)
      if (mask & (size_t{1} << i)) s.push_back(all[i]);
    out.push_back(s);
  }
  return out;
}

}  // namespace

TEST_CASE("validity rules: one reason per invalid axis value", "[scene]") {
  AxisPoint p;
  p.lights = {LightType::Dir, LightType::Sphere};
  CHECK(!invalidReason(model("standard"), p));
  auto r = invalidReason(model("cloth"), p);
  REQUIRE(r);
  CHECK(r->find("'sphere' lights") != std::string::npos);
  p.lights = {LightType::Dir};
  p.environment = EnvironmentMode::IblAnalytic;
  CHECK(invalidReason(model("cloth"), p));
  p.environment = EnvironmentMode::None;
  p.features = {"clearcoat"};
  CHECK(invalidReason(model("cloth"), p));
  CHECK(!invalidReason(model("standard"), p));
  CHECK(!parsePrecision("fp64"));  // an unknown precision is refused where it is read
  p.precision = Precision::Fp16;
  CHECK(!parseQuality("ultra"));  // an unknown quality level is refused where it is read
  p.quality = Quality::Low;
  CHECK(!invalidReason(model("standard"), p));
}

TEST_CASE("valid combination counts equal a brute-force enumeration of the product", "[scene]") {
  for (const auto& m : test::shippedLibrary().models()) {
    size_t product = 1, brute = 0;
    for (const auto& a : axisSizes(m)) product *= a.values;
    std::vector<std::string> features;
    for (const auto& f : m.features) features.push_back(f.name);
    for (const auto& fs : subsets(features))
      for (const auto& ls : subsets(allLightTypes()))
        for (const auto& e : allEnvironmentModes())
          for (Precision pr : allPrecisions())
            for (Quality q : allQualities()) brute += !invalidReason(m, AxisPoint{fs, ls, e, pr, q});
    INFO(m.name);
    CHECK(validCombinationCount(m) == brute);
    CHECK(brute <= product);
  }
  // standard: 2^3 features x 2^7 light sets x 4 environments x 2 precisions x 3 qualities.
  CHECK(validCombinationCount(model("standard")) == 24576);
  // cloth: no features, 2^3 light sets (dir, point, spot), 3 environments, 2 x 3.
  CHECK(validCombinationCount(model("cloth")) == 8 * 3 * 2 * 3);
}

TEST_CASE("quality: defaulted roles follow the table, chosen roles keep the material's brick", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  CHECK(model("standard").quality.at("low").at("sh_irradiance") == "sh_l1_irradiance");
  MaterialDesc m = material("filament_plastic");
  MaterialDesc low = applyQuality(m, Quality::Low, lib);
  CHECK(low.bricks.at("sh_irradiance") == "sh_l1_irradiance");
  CHECK(low.bricks.at("energy_compensation") == "energy_compensation_none");
  CHECK(applyQuality(m, Quality::High, lib).bricks == m.bricks);
  CHECK(applyQuality(m, Quality::Medium, lib).bricks.at("sphere_horizon_wrap") == "horizon_wrap_hermite");
  // The material chose this role itself: quality leaves it alone.
  MaterialDesc chose = m;
  chose.bricks["sh_irradiance"] = "sh9_irradiance";
  chose.brickLocations["sh_irradiance"] = SourceLocation("x.json", 3, 4);
  CHECK(applyQuality(chose, Quality::Low, lib).bricks.at("sh_irradiance") == "sh9_irradiance");
}

TEST_CASE("light methods: the material's choice, else the quality level's, else the model's default", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const LightMethodChoice* sphere = model("standard").findLightMethod(LightType::Sphere);
  REQUIRE(sphere);
  CHECK(sphere->defaultMethod == "ltc");
  CHECK(sphere->quality.at("low") == "representative_point");
  CHECK(!model("standard").findLightMethod(LightType::Point));  // one way only: no choice
  const MaterialDesc m = material("filament_plastic");
  CHECK(m.lightMethod(LightType::Sphere) == "ltc");
  CHECK(m.lightMethod(LightType::Point).empty());
  auto roles = [&](const MaterialDesc& mat, Quality q) {
    Permutation p;
    p.material = &mat;
    p.lights = {LightType::Dir, LightType::Sphere, LightType::Tube};
    p.quality = q;
    std::map<std::string, std::string> out;
    for (const auto& [role, brick] : boundRoles(lib, p)) out[role] = brick;
    const std::string glsl = emitPermutation(lib, p).glsl;
    out["#ltc"] = glsl.find("#define MB_LIGHT_SPHERE_LTC 1") != std::string::npos ? "yes" : "no";
    out["#rp"] = glsl.find("#define MB_LIGHT_SPHERE_REPRESENTATIVE_POINT 1") != std::string::npos ? "yes" : "no";
    out["#table"] = p.readsLtcTable() ? "yes" : "no";
    return out;
  };
  // High: LTC, and its roles exist beside the representative point's (which it mixes in).
  auto high = roles(m, Quality::High);
  CHECK(high.at("sphere_light_ltc_cv") == "sphere_ltc_cv");
  CHECK(high.at("tube_light_ltc") == "tube_ltc_polygon");
  CHECK(high.count("sphere_light_point"));
  CHECK(high.at("#ltc") == "yes");
  CHECK(high.at("#table") == "yes");
  // Low: the level's representative point; no LTC role, no table.
  const MaterialDesc low = applyQuality(m, Quality::Low, lib);
  CHECK(low.lightMethod(LightType::Tube) == "representative_point");
  auto lowRoles = roles(low, Quality::Low);
  CHECK(!lowRoles.count("sphere_light_ltc_cv"));
  CHECK(!lowRoles.count("tube_light_ltc"));
  CHECK(lowRoles.count("tube_light_point"));
  CHECK(lowRoles.at("#rp") == "yes");
  CHECK(lowRoles.at("#table") == "no");
  // A material's own choice, in either form, outlives the quality level.
  const std::string json = R"({"name": "chose", "model": "standard", "lightMethods": {"sphere": "ltc"},
    "bricks": {"roughness": "roughness_clamped", "diffuse": "diffuse_lambert", "specular_d": "d_ggx",
               "specular_v": "v_smith_ggx_correlated", "fresnel": "f_schlick"}})";
  const MaterialDesc chose = parseMaterialJson(json, "chose.json", lib);
  CHECK(chose.lightMethodLocations.at("sphere").line == 1);
  const MaterialDesc choseLow = applyQuality(chose, Quality::Low, lib);
  CHECK(choseLow.lightMethod(LightType::Sphere) == "ltc");
  CHECK(choseLow.lightMethod(LightType::Tube) == "representative_point");
  const MaterialDesc macro = parseMaterialMacro(
      "#define MATERIAL chose\n#define MODEL standard\n#define LIGHT_METHOD_sphere ltc\n"
      "#define BRICK_roughness roughness_clamped\n#define BRICK_diffuse diffuse_lambert\n"
      "#define BRICK_specular_d d_ggx\n#define BRICK_specular_v v_smith_ggx_correlated\n#define BRICK_fresnel f_schlick\n",
      "chose.mat", lib);
  CHECK(macro.lightMethods == chose.lightMethods);
  CHECK(macro.lightMethodLocations.at("sphere").line == 3);
}

TEST_CASE("light methods: a material naming an unknown light or method is told where", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto errorsOf = [&](const std::string& methods) {
    const std::string json = R"({"name": "x", "model": "standard", "lightMethods": )" + methods + R"(,
    "bricks": {"roughness": "roughness_clamped", "diffuse": "diffuse_lambert", "specular_d": "d_ggx",
               "specular_v": "v_smith_ggx_correlated", "fresnel": "f_schlick"}})";
    try {
      parseMaterialJson(json, "x.json", lib);
    } catch (const DiagnosticError& e) {
      return e.diagnostics();
    }
    return std::vector<Diagnostic>{};
  };
  auto unknownLight = errorsOf(R"({"sphre": "ltc"})");
  REQUIRE(unknownLight.size() == 1);
  CHECK(unknownLight[0].code == "E-UNKNOWN-NAME");
  CHECK(unknownLight[0].where.column == 53);  // the key
  CHECK(unknownLight[0].suggestion == "did you mean 'sphere'?");
  auto point = errorsOf(R"({"point": "ltc"})");
  REQUIRE(point.size() == 1);
  CHECK(point[0].message.find("offers no methods for light 'point'") != std::string::npos);
  auto method = errorsOf(R"({"tube": "representative"})");
  REQUIRE(method.size() == 1);
  CHECK(method[0].where.column == 61);  // the value
  CHECK(method[0].message.find("expected one of 'ltc', 'representative_point'") != std::string::npos);
  auto notText = errorsOf(R"({"tube": 1})");
  REQUIRE(notText.size() == 1);
  CHECK(notText[0].code == "E-FIELD-TYPE");
}

namespace {

// The codes of the diagnostics the library loader gives after replacing `from` by `to` in a
// copy of the shipped shaderlib's models/<modelFile>; every one must have a position.
std::vector<std::string> libraryCodesAfterEdit(const std::string& modelFile, const std::string& from,
                                               const std::string& to) {
  namespace fs = std::filesystem;
  fs::path root = fs::temp_directory_path() / ("mb_scene_library_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::copy(test::sourceDir() / "shaderlib", root, fs::copy_options::recursive);
  std::string p = (root / "models" / modelFile).string();
  std::string text = test::readFile(p);
  REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), to);
  std::ofstream(p) << text;
  std::vector<Diagnostic> ds;
  try {
    ShaderLibrary::load(root);
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  fs::remove_all(root);
  std::vector<std::string> codes;
  for (const auto& d : ds) {
    INFO(d.message);
    CHECK(d.where.line > 0);
    codes.push_back(d.code);
  }
  return codes;
}

}  // namespace

TEST_CASE("the quality table is checked at load: unknown level, role, brick of another slot", "[scene]") {
  auto codes =
      libraryCodesAfterEdit("cloth.json", R"("medium": {})",
                            R"("medium": {"sh_irradianse": "sh9_irradiance", "mip_mapping": "d_ggx"}, "ultra": {})");
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-FIELD") == 1);  // "ultra"
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-ROLE") == 1);
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-BRICK") == 1);
}

TEST_CASE("light methods are checked at load: unknown light, method, default; a role's method every light offers",
          "[scene]") {
  auto codes = libraryCodesAfterEdit(
      "standard.json", R"("lightMethods": [)",
      R"("lightMethods": [{"light": "sphre", "methods": ["a"], "default": "a", "description": "x"},
                          {"light": "rect", "methods": ["a", "a"], "default": "b", "quality": {"low": "c"}, "description": "x"},)");
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-NAME") == 3);    // sphre, default b, low c
  CHECK(std::count(codes.begin(), codes.end(), "E-DUPLICATE-NAME") == 1);  // "a" twice
  auto roleCodes = libraryCodesAfterEdit("standard.json", R"("lights": ["sphere"], "method": "ltc")",
                                         R"("lights": ["sphere", "point"], "method": "ltc")");
  CHECK(roleCodes == std::vector<std::string>{"E-UNKNOWN-NAME"});  // point offers no "ltc"
  // A role's toleranceScale must not shrink the tolerance, nor be absurd.
  auto scaleCodes = libraryCodesAfterEdit("standard.json", R"("factor": 127.32395447351627)", R"("factor": 0.5)");
  CHECK(scaleCodes == std::vector<std::string>{"E-OUT-OF-RANGE"});
}

TEST_CASE("brick rules are checked at load: unknown role, brick of another slot, no bricks, no reason", "[scene]") {
  auto codes = libraryCodesAfterEdit(
      "standard.json", R"("incompatible": [)",
      R"("incompatible": [{"bricks": {"dfg_lutt": "dfg_lut_ue4", "env_brdf": "d_ggx"}, "reason": "x"},
                          {"bricks": {}, "reason": "x"}, {"bricks": {"dfg_lut": "dfg_lut_ue4"}},)");
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-ROLE") == 1);
  CHECK(std::count(codes.begin(), codes.end(), "E-UNKNOWN-BRICK") == 1);
  CHECK(std::count(codes.begin(), codes.end(), "E-FIELD-TYPE") == 1);     // no bricks
  CHECK(std::count(codes.begin(), codes.end(), "E-MISSING-FIELD") == 1);  // no reason
}

TEST_CASE("brick rules: an incompatible pair is invalid only where both roles are active and bound to it", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const ShadingModel& standard = model("standard");
  REQUIRE(standard.incompatible.size() == 2);
  MaterialDesc m = material("ue4_metal");
  m.bricks["env_brdf"] = "env_brdf_approx_nonmetal";
  m.brickLocations["env_brdf"] = SourceLocation("metal.json", 9, 17);
  Permutation p;
  p.material = &m;
  p.lights = {LightType::Dir};
  p.environment = EnvironmentMode::IblAnalytic;
  auto broken = brokenBrickRule(standard, p);
  REQUIRE(broken);
  CHECK(broken->rule == &standard.incompatible[1]);
  CHECK(broken->message.find("env_brdf = env_brdf_approx_nonmetal") != std::string::npos);
  CHECK(invalidReason(standard, p) == broken->message);
  CHECK(invalidLocation(standard, p).line == 9);
  // env_brdf is not called with the LUT, nor energy compensation without an IBL mode.
  for (EnvironmentMode env : {EnvironmentMode::IblLut, EnvironmentMode::Sh, EnvironmentMode::None}) {
    p.environment = env;
    CHECK(!invalidReason(standard, p));
  }
  // Low quality binds energy_compensation_none: the pair is gone.
  MaterialDesc low = applyQuality(m, Quality::Low, lib);
  p.material = &low;
  p.environment = EnvironmentMode::IblAnalytic;
  p.quality = Quality::Low;
  CHECK(!brokenBrickRule(standard, p));
  // The UE4-layout LUT with the DESIGN.md-layout compensation, in ibl_lut only.
  MaterialDesc ue4Lut = material("ue4_metal");
  ue4Lut.bricks["dfg_lut"] = "dfg_lut_ue4";
  p.material = &ue4Lut;
  p.quality = Quality::High;
  p.environment = EnvironmentMode::IblLut;
  CHECK(brokenBrickRule(standard, p));
  // Not chosen in the file: at the model's name.
  CHECK(invalidLocation(standard, p).line == ue4Lut.modelWhere.line);
  CHECK(ue4Lut.modelWhere.line > 0);
  p.environment = EnvironmentMode::IblAnalytic;
  CHECK(!brokenBrickRule(standard, p));
  ue4Lut.bricks["energy_compensation"] = "energy_compensation_none";
  p.environment = EnvironmentMode::IblLut;
  CHECK(!brokenBrickRule(standard, p));
}

TEST_CASE("a scene that needs a permutation breaking a brick rule is refused at the material's entry", "[scene]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("mb_scene_rule_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto j = nlohmann::json::parse(test::readFile(test::sourceDir() / "materials" / "ue4_metal.json"));
  j["name"] = "mobile_metal";
  j["bricks"]["env_brdf"] = "env_brdf_approx_nonmetal";
  std::ofstream(dir / "metal.json") << j.dump(2);
  auto write = [&](const std::string& quality) {
    std::ofstream(dir / "scene.json") << R"({"lights": [{"type": "dir"}], "environment": ["sh", "ibl_analytic"],
      "quality": )" << quality << R"(, "materials": [{"file": "metal.json"}]})";
    return loadScene((dir / "scene.json").string(), test::shippedLibrary());
  };
  // Low quality drops the compensation: valid.
  CHECK(planScene(write(R"("low")"), test::shippedLibrary()).required.size() == 2);
  std::vector<Diagnostic> ds;
  try {
    planScene(write(R"(["low", "high"])"), test::shippedLibrary());
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  fs::remove_all(dir);
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == "E-PERMUTATION-INVALID");
  CHECK(ds[0].where.line == 2);  // the material's entry in the scene
  CHECK(ds[0].message.find("quality 'high'") != std::string::npos);
  CHECK(ds[0].message.find("brick chosen at") != std::string::npos);
}

TEST_CASE("folding: neutral in every use folds; a non-neutral, unstated or surface-written input keeps", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc cc = material("clearcoat_metal");
  CHECK(!foldBlocker(cc, "clearcoat", {use({{"clearCoat", {0.0}}})}, lib));
  auto half = foldBlocker(cc, "clearcoat", {use({{"clearCoat", {0.0}}}), use({{"clearCoat", {0.5}}})}, lib);
  REQUIRE(half);
  CHECK(half->find("0.5") != std::string::npos);
  auto unstated = foldBlocker(cc, "clearcoat", {MaterialUse{}}, lib);  // clearCoat is a run-time input
  REQUIRE(unstated);
  CHECK(unstated->find("unstated") != std::string::npos);
  auto surface = foldBlocker(material("worn_car_paint"), "clearcoat", {use({{"clearCoat", {0.0}}})}, lib);
  REQUIRE(surface);
  CHECK(surface->find("surface code") != std::string::npos);
  CHECK(foldBlocker(cc, "sheen", {MaterialUse{}}, lib));  // not enabled

  MaterialDesc folded = foldFeatures(cc, {"clearcoat"}, lib);
  CHECK(folded.features.empty());
  CHECK(!folded.param("clearCoat"));
  CHECK(!folded.param("clearCoatRoughness"));
  CHECK(!folded.bricks.count("clearcoat_d"));
  CHECK(!folded.bricks.count("f0_clearcoat"));
  CHECK(folded.bricks.count("specular_d"));

  // The feature-complete form: every feature on, added inputs at the use's / neutral values.
  MaterialDesc full = featureComplete(folded, use({{"clearCoat", {0.0}}}), lib);
  CHECK(full.features == std::vector<std::string>{"clearcoat", "anisotropy", "sheen"});
  REQUIRE(full.param("clearCoat"));
  CHECK(full.param("clearCoat")->constant);
  CHECK(full.param("clearCoat")->value == std::vector<double>{0.0});
  CHECK(full.param("anisotropy")->value == std::vector<double>{0.0});
  CHECK(full.param("sheenColor")->value == std::vector<double>{0.0, 0.0, 0.0});
  CHECK(full.param("sheenRoughness")->value == model("standard").inputs.back().defaultValue);
  CHECK(full.bricks.at("sheen_d") == "d_charlie");
  CHECK(full.param("roughness")->constant == folded.param("roughness")->constant);
  // A feature the (specialized) material kept keeps its run-time input, whatever the use says.
  MaterialDesc kept = featureComplete(cc, use({{"clearCoat", {0.0}}}), lib);
  CHECK(!kept.param("clearCoat")->constant);
}

TEST_CASE("example scenes: required counts, far below possible, sorted keys, deterministic", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  struct Expect {
    std::string file;
    size_t required;
  };
  // showroom: 5 materials (one listed twice) x precision x2; mobile: 3 x quality x2;
  // gallery: 4 used glTF materials + 1 x environment x2; gallery.gltf: its 4 used materials.
  for (const auto& e :
       std::vector<Expect>{{"showroom.json", 10}, {"mobile.json", 6}, {"gallery.json", 10}, {"gallery.gltf", 4}}) {
    INFO(e.file);
    ScenePlan plan = planScene(exampleScene(e.file), lib);
    CHECK(plan.required.size() == e.required);
    CHECK(plan.possible >= 100 * plan.required.size());
    auto keys = keysOf(plan);
    CHECK(std::is_sorted(keys.begin(), keys.end()));
    CHECK(std::adjacent_find(keys.begin(), keys.end()) == keys.end());
    CHECK(keysOf(planScene(exampleScene(e.file), lib)) == keys);
  }
  ScenePlan showroom = planScene(exampleScene("showroom.json"), lib);
  CHECK(showroom.possible == 5 * 24576);
  CHECK(showroom.requiredAxes.size() == 1);
  CHECK(showroom.requiredAxes[0].axis == "precision");
  auto keys = keysOf(showroom);
  CHECK(std::count(keys.begin(), keys.end(),
                   "clearcoat_metal.standard.dir+point+sphere.ibl_lut.fp16.without-clearcoat") == 1);
  CHECK(std::count(keys.begin(), keys.end(), "satin_sheen.standard.dir+point+sphere.ibl_lut.fp32.without-sheen") == 1);
  CHECK(std::count(keys.begin(), keys.end(), "brushed_metal.standard.dir+point+sphere.ibl_lut.fp32") == 1);
  CHECK(std::count(keys.begin(), keys.end(), "worn_car_paint.standard.dir+point+sphere.ibl_lut.fp32") == 1);
  ScenePlan mobile = planScene(exampleScene("mobile.json"), lib);
  auto mk = keysOf(mobile);
  CHECK(std::count(mk.begin(), mk.end(), "velvet_green.cloth.dir+point.sh.fp16.low") == 1);
  CHECK(std::count(mk.begin(), mk.end(), "velvet_green.cloth.dir+point.sh.fp16.medium") == 1);
  for (const auto& p : mobile.required)
    if (p.quality == Quality::Low) CHECK(p.material->bricks.at("sh_irradiance") == "sh_l1_irradiance");
  ScenePlan gallery = planScene(exampleScene("gallery.gltf"), lib);
  CHECK(std::count_if(gallery.required.begin(), gallery.required.end(), [](const Permutation& p) {
          return p.key() == "Lacquered_Oak.standard.dir+point.none.fp32.without-clearcoat";
        }) == 1);
  std::string text = explainText(showroom, showroom.required.size(), 9);
  CHECK(text.find("required       10   (5 materials x precision x2)") != std::string::npos);
  CHECK(text.find("folded clearcoat") != std::string::npos);
  CHECK(text.find("kept   clearcoat: the surface code uses m.clearCoat") != std::string::npos);
}

TEST_CASE("a model that cannot shade the scene's lights is E-PERMUTATION-INVALID at the material", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  SceneDesc s = parseSceneJson(R"({"lights": [{"type": "dir"}, {"type": "sphere", "name": "bulb"}],
 "materials": [{"file": "../../materials/velvet_green.json"}]})",
                               (test::sourceDir() / "examples/scenes/t.json").string(), lib);
  try {
    planScene(s, lib);
    FAIL("no error");
  } catch (const DiagnosticError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    const Diagnostic& d = e.diagnostics()[0];
    CHECK(d.code == "E-PERMUTATION-INVALID");
    CHECK(d.where.line == 2);
    CHECK(d.message.find("'bulb'") != std::string::npos);
    CHECK(d.suggestion.find("'standard'") != std::string::npos);
  }
}

TEST_CASE("diffKeys lists missing and extra keys, empty when nothing is missing", "[scene]") {
  CHECK(diffKeys({"a", "b"}, {"b", "a", "c"}).empty());
  CHECK(diffKeys({"a", "b"}, {"b", "c"}) == "- a\n+ c\n");
}

TEST_CASE("verify: a package missing one required permutation fails with the key; a bad manifest is bad input",
          "[scene][cli][vulkan]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("mb_scene_verify_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string scene = (test::sourceDir() / "examples/scenes/mobile.json").string();
  ScenePlan plan = planScene(loadScene(scene, test::shippedLibrary()), test::shippedLibrary());
  auto keys = keysOf(plan);
  auto write = [&](size_t skip) {
    std::string m = R"({"permutations": [)";
    for (size_t i = 0, n = 0; i < keys.size(); ++i)
      if (i != skip) m += std::string(n++ ? "," : "") + R"({"key": ")" + keys[i] + R"("})";
    std::ofstream(dir / "manifest.json") << m << "]}";
  };
  write(keys.size());
  auto ok = test::runCli("verify --scene " + scene + " " + dir.string());
  INFO(ok.output);
  CHECK(ok.exitCode == 0);
  write(2);
  auto missing = test::runCli("verify --scene " + scene + " " + dir.string());
  INFO(missing.output);
  CHECK(missing.exitCode == 1);
  CHECK(missing.output.find("- " + keys[2] + "\n") != std::string::npos);
  CHECK(missing.output.find("E-PACKAGE-MISSING-PERMUTATION") != std::string::npos);
  // A manifest that is not a package's, or not JSON, or not there: bad input, exit 3, at a position.
  struct Bad {
    std::string manifest, code, at;
  };
  const std::string file = (dir / "manifest.json").string();
  for (const Bad& b : {Bad{"{\"format\": 1}", "E-PACKAGE-MANIFEST", file + ":1:1"},
                       Bad{"{\"permutations\": [\n  {\"name\": 1}]}", "E-PACKAGE-MANIFEST", file + ":2:3"},
                       Bad{"{\"permutations\": [\n  {\"key\": 7}]}", "E-FIELD-TYPE", file + ":2:11"},
                       Bad{"{\"permutations\": [,]}", "E-JSON-SYNTAX", file + ":1:19"}}) {
    std::ofstream(dir / "manifest.json") << b.manifest;
    auto r = test::runCli("verify --scene " + scene + " " + dir.string());
    INFO(b.manifest << "\n" << r.output);
    CHECK(r.exitCode == 3);
    CHECK(r.output.find(b.at + ": error[" + b.code + "]") != std::string::npos);
  }
  fs::remove(dir / "manifest.json");
  auto absent = test::runCli("verify --scene " + scene + " " + dir.string());
  INFO(absent.output);
  CHECK(absent.exitCode == 3);
  CHECK(absent.output.find("E-FILE-NOT-FOUND") != std::string::npos);
  fs::remove_all(dir);
}
