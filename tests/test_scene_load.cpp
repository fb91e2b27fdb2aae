// Scene loading (docs/scenes.md): scene JSON errors at their positions, glTF scenes (lights
// the nodes reference, materials the meshes use), merging a material listed twice.
#include <catch2/catch.hpp>

#include <filesystem>

#include "load/gltf_container.hpp"
#include "load/scene_desc.hpp"
#include "support/gltf_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

// A scene file "written" in examples/scenes/, so that material paths resolve as there.
std::string sceneFile() { return (test::sourceDir() / "examples/scenes/test.json").string(); }

std::vector<Diagnostic> errorsOf(const std::string& json) {
  try {
    parseSceneJson(json, sceneFile(), test::shippedLibrary());
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

const Diagnostic* find(const std::vector<Diagnostic>& ds, const std::string& code) {
  for (const auto& d : ds)
    if (d.code == code) return &d;
  return nullptr;
}

const std::string kClearcoat = R"("../../materials/clearcoat_metal.json")";

}  // namespace

TEST_CASE("scene JSON: axes, lights and uses are read", "[scene]") {
  SceneDesc s = parseSceneJson(R"({"name": "t", "lights": [{"type": "point"}, {"type": "dir", "name": "sun"}],
    "environment": ["ibl_lut", "sh"], "precision": "fp16", "quality": ["high", "low"], "targets": ["spirv", "glsl450"],
    "materials": [{"file": )" + kClearcoat +
                                   R"(, "uses": [{"clearCoat": 0.25}]}]})",
                               sceneFile(), test::shippedLibrary());
  CHECK(s.name == "t");
  CHECK(lightTypeNames(s.lightTypes()) == std::vector<std::string>{"dir", "point"});
  CHECK(s.environments ==
        std::vector<EnvironmentMode>{EnvironmentMode::Sh, EnvironmentMode::IblLut});  // canonical order
  CHECK(s.precisions == std::vector<Precision>{Precision::Fp16});
  CHECK(s.qualities == std::vector<Quality>{Quality::Low, Quality::High});
  CHECK(targetNames(s.targets) == std::vector<std::string>{"spirv", "glsl450"});
  REQUIRE(s.materials.size() == 1);
  REQUIRE(s.materials[0].uses.size() == 1);
  CHECK(s.materials[0].uses[0].values.at("clearCoat") == std::vector<double>{0.25});
  CHECK(s.materials[0].where.line == 3);
}

TEST_CASE("scene JSON: a material listed twice is merged, its uses appended", "[scene]") {
  SceneDesc s = parseSceneJson(R"({"materials": [{"file": )" + kClearcoat + R"(, "uses": [{"clearCoat": 0}]},
    {"file": )" + kClearcoat + R"(, "uses": [{"clearCoat": 1}]}]})",
                               sceneFile(), test::shippedLibrary());
  REQUIRE(s.materials.size() == 1);
  CHECK(s.materials[0].uses.size() == 2);
}

TEST_CASE("scene JSON errors carry codes and positions", "[scene]") {
  auto ds = errorsOf(R"({"lights": [{"type": "spher"}], "environment": "ibl",
 "precision": ["fp32", "fp64"], "quality": "ultra", "targets": ["spirv", "dxil"], "ligths": [],
 "materials": [{"file": )" +
                     kClearcoat + R"(, "uses": [{"clearcoat": 0}, {"roughnes": 0.2},
   {"clearCoat": 2.0}, {"baseColor": [1, 1]}, {"metallic": 0.5}]},
  {"file": "nope.json"}]})");
  auto expect = [&](const std::string& code, int line, const std::string& suggestion) {
    INFO(code);
    const Diagnostic* d = find(ds, code);
    REQUIRE(d);
    CHECK(d->where.line == line);
    CHECK(d->where.column > 0);
    CHECK(d->suggestion.find(suggestion) != std::string::npos);
  };
  expect("E-SCENE-LIGHT-TYPE", 1, "sphere");
  expect("E-SCENE-AXIS-VALUE", 1, "");  // environment 'ibl' (then precision, quality)
  expect("E-SCENE-TARGET", 2, "");
  expect("E-UNKNOWN-FIELD", 2, "lights");
  expect("E-SCENE-UNKNOWN-INPUT", 3, "clearCoat");
  expect("E-SCENE-VALUE-RANGE", 4, "");
  expect("E-SCENE-VALUE-TYPE", 4, "");
  expect("E-SCENE-CONSTANT", 4, "run-time input");
  expect("E-FILE-NOT-FOUND", 5, "");
  size_t axisErrors = 0, unknownInputs = 0;
  for (const auto& d : ds) {
    axisErrors += d.code == "E-SCENE-AXIS-VALUE";
    unknownInputs += d.code == "E-SCENE-UNKNOWN-INPUT";
  }
  CHECK(axisErrors == 3);  // environment, precision, quality
  CHECK(unknownInputs == 2);
  CHECK(find(ds, "E-SCENE-UNKNOWN-INPUT")->message.find("clearcoat") != std::string::npos);
}

TEST_CASE("scene JSON without materials, or with empty uses, is refused", "[scene]") {
  CHECK(find(errorsOf(R"({"name": "x", "materials": []})"), "E-SCENE-NO-MATERIALS"));
  CHECK(find(errorsOf(R"({"materials": [{"file": )" + kClearcoat + R"(, "uses": []}]})"), "E-SCENE-NO-USES"));
  CHECK(find(errorsOf(R"({"environment": []})"), "E-FIELD-TYPE"));
}

TEST_CASE("glTF scene: referenced lights and the materials meshes use", "[scene]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  SceneDesc s = loadScene((test::sourceDir() / "examples/scenes/gallery.gltf").string(), lib);
  // The spot light is defined but no node references it.
  CHECK(lightTypeNames(s.lightTypes()) == std::vector<std::string>{"dir", "point"});
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].name == "sun");
  CHECK(s.lights[0].where.line > 1);
  std::vector<std::string> names;
  for (const auto& m : s.materials) names.push_back(m.material.name);
  // "Unused Gold" is used by no mesh: not part of the scene.
  CHECK(names == std::vector<std::string>{"Lacquered_Oak", "Car_Paint", "Brushed_Steel", "Plaster"});
  CHECK(s.environments == std::vector<EnvironmentMode>{EnvironmentMode::None});
  CHECK(s.precisions == std::vector<Precision>{Precision::Fp32});
  CHECK(s.qualities == std::vector<Quality>{Quality::High});
  CHECK(targetNames(s.targets) == std::vector<std::string>{"spirv"});
  // clearcoatFactor 0 became the constant 0 of an enabled clear coat.
  const MaterialParam* cc = s.materials[0].material.param("clearCoat");
  REQUIRE(cc);
  CHECK(cc->constant);
  CHECK(cc->value == std::vector<double>{0.0});
}

TEST_CASE("glTF scene: a light's matbricks_area_light extras make it a rectangle or disk light", "[scene][gltf]") {
  // docs/gltf.md "Area lights": KHR_lights_punctual has no area lights; the convention rides in
  // a light's extras, and a reader without it sees the light's own type.
  const ShaderLibrary& lib = test::shippedLibrary();
  const std::string gallery = test::readFile(test::sourceDir() / "examples/scenes/gallery.gltf");
  auto withExtras = [&](const std::string& light, const std::string& extras) {
    const std::string name = "\"name\": \"" + light + "\",";
    const size_t at = gallery.find(name);
    REQUIRE(at != std::string::npos);
    return gallery.substr(0, at + name.size()) + " \"extras\": {\"note\": 1, \"matbricks_area_light\": " + extras +
           "}," + gallery.substr(at + name.size());
  };
  {
    test::TempFile f("area_rect.gltf", withExtras("desk lamp", R"({"shape": "rect", "size": [1.0, 0.5]})"));
    CHECK(lightTypeNames(loadScene(f.path(), lib).lightTypes()) == std::vector<std::string>{"dir", "rect"});
  }
  {
    test::TempFile f("area_disk.gltf", withExtras("desk lamp", R"({"shape": "disk", "size": [0.3, 0.3]})"));
    CHECK(lightTypeNames(loadScene(f.path(), lib).lightTypes()) == std::vector<std::string>{"dir", "disk"});
  }
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"desk lamp", R"({"shape": "hexagon", "size": [1, 1]})"},
      {"desk lamp", R"({"shape": "rect", "size": [1, -2]})"},
      {"desk lamp", R"({"shape": "rect"})"},
      {"sun", R"({"shape": "rect", "size": [1, 1]})"},
  };
  for (const auto& [light, extras] : bad) {
    const std::string text = withExtras(light, extras);
    test::TempFile f("area_bad.gltf", text);
    INFO(extras);
    std::vector<Diagnostic> ds;
    try {
      loadScene(f.path(), lib);
    } catch (const DiagnosticError& e) {
      ds = e.diagnostics();
    }
    REQUIRE(!ds.empty());
    CHECK((ds[0].code == "E-SCENE-AREA-LIGHT" || ds[0].code == "E-MISSING-FIELD"));
    // Located inside the extras, not at the file's start.
    CHECK(ds[0].where.line >= test::positionOf(text, "matbricks_area_light").first);
  }
}

// The scene walk builds a tree only of the node members it reads (load/gltf_container.hpp,
// loadGltfSceneJson): the others are blanked in place, so what remains keeps its position, and
// a node left with none of them is still an object (no type error).
TEST_CASE("glTF scene: nodes' unread members are skipped, positions kept", "[scene][gltf]") {
  auto gltf = [](const std::string& mesh) {
    return "{\n  \"asset\": {\"version\": \"2.0\"},\n"
           "  \"materials\": [{\"name\": \"Red\", \"pbrMetallicRoughness\": {\"baseColorFactor\": [0.8, 0.2, 0.2, "
           "1]}}],\n  \"meshes\": [{\"primitives\": [{\"material\": 0}]}],\n  \"nodes\": [\n"
           "    {\"name\": \"root\", \"matrix\": [1, 0, 0, 0,\n      0, 1, 0, 0,\n      0, 0, 1, 0,\n      0, 0, 0, "
           "1], \"children\": [1, 2]},\n    {\"name\": \"only a name\", \"extras\": {\"a\": [1, {\"b\": 2}]}},\n"
           "    {\"name\": \"last\", \"mesh\": " +
           mesh + "}\n  ]\n}\n";
  };
  const ShaderLibrary& lib = test::shippedLibrary();
  test::TempFile good("scene_nodes_good.gltf", gltf("0"));
  SceneDesc s = loadScene(good.path(), lib);
  REQUIRE(s.materials.size() == 1);
  CHECK(s.materials[0].material.name == "Red");
  GltfContainerInfo info;
  const JsonDocument doc = loadGltfSceneJson(good.path(), info);
  const nlohmann::json& nodes = doc.root().at("nodes");
  CHECK(nodes[0].at("children").size() == 2);
  CHECK(nodes[0].at("matrix") == 0);  // blanked: its node has members the walk reads
  CHECK(nodes[1] == nlohmann::json::object());
  CHECK(nodes[2].at("mesh") == 0);

  test::TempFile bad("scene_nodes_bad.gltf", gltf("7"));
  std::vector<Diagnostic> ds;
  try {
    loadScene(bad.path(), lib);
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  REQUIRE(ds.size() == 1);
  CHECK(ds[0].code == "E-GLTF-INDEX");
  test::requireAt(ds[0], {11, 30});  // the 7, after the blanked name on its line
}

TEST_CASE("scene JSON pulls a glTF file in and adds its own materials", "[scene]") {
  SceneDesc s = loadScene((test::sourceDir() / "examples/scenes/gallery.json").string(), test::shippedLibrary());
  CHECK(lightTypeNames(s.lightTypes()) == std::vector<std::string>{"dir", "point"});
  CHECK(s.materials.size() == 5);
  CHECK(s.environments == std::vector<EnvironmentMode>{EnvironmentMode::None, EnvironmentMode::IblLut});
}
