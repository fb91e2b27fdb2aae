// Scene JSON (docs/scenes.md "Scene JSON") and the entry point for both scene forms. This file
// checks what is JSON about a scene and each axis value; the material files are loaded by
// loadMaterialFile (every description form), and the uses' values are checked against the
// loaded materials (load/scene_uses.cpp).
#include <algorithm>
#include <filesystem>

#include "core/json_fields.hpp"
#include "core/target.hpp"
#include "core/vocabulary.hpp"
#include "load/material_resolve.hpp"
#include "load/project_files.hpp"
#include "load/scene_desc.hpp"
#include "load/scene_gltf.hpp"
#include "load/scene_uses.hpp"

namespace mb {

namespace {

// A glTF scene with neither KHR_lights_punctual lights nor EXT_lights_image_based says nothing
// about its lighting. Planned with `none` it would get emission-only permutations (every
// texture that does not feed emission compiled away), which is not what a viewer shows: glTF
// viewers such as Khronos's glTF Sample Viewer light such a file by default with an
// environment map. So it gets `ibl_lut` -- the image-based light and its SH irradiance --
// and a warning that says how to choose otherwise (issue 18; docs/scenes.md).
Diagnostic noLightsWarning(const SourceLocation& where) {
  return {Severity::Warning, "W-SCENE-GLTF-NO-LIGHTS", where,
          "the glTF scene has no KHR_lights_punctual light and no EXT_lights_image_based: it is planned "
          "with environment ibl_lut (image-based light), as glTF viewers show such files",
          "to choose the lights and environment, name the file in a scene JSON's \"gltf\" with "
          "\"lights\" and \"environment\""};
}

using nlohmann::json;

// A scene is a handful of levels deep; anything deeper is refused before the position scan.
constexpr int kMaxSceneJsonDepth = 64;
// A scene's values grow with its materials and their uses: a million is far beyond any real
// scene and bounds its tree (docs/formats.md "Input files").
constexpr size_t kMaxSceneJsonValues = 1'000'000;

bool isGltf(const std::string& path) {
  std::string ext = lowerExtension(path);
  return ext == ".gltf" || ext == ".glb";
}

// Scene paths are relative to the scene file. Unlike a material's own includes they may leave
// its directory: a scene gathers materials from a library elsewhere (docs/scenes.md).
std::string relativeTo(const std::string& sceneFile, const std::string& written) {
  std::filesystem::path p(written);
  if (p.is_absolute()) return written;
  return (std::filesystem::path(sceneFile).parent_path() / p).lexically_normal().string();
}

class SceneJsonReader {
 public:
  SceneJsonReader(const JsonDocument& doc, const ShaderLibrary& lib, DiagnosticSink& sink)
      : doc_(doc), lib_(lib), f_(doc, sink), sink_(sink) {}

  SceneDesc run() {
    scene_.file = doc_.file();
    scene_.name = std::filesystem::path(doc_.file()).stem().string();
    if (!f_.object("", {},
                   {"name", "description", "lights", "environment", "precision", "quality", "targets", "optimization",
                    "gltf", "materials"},
                   "scene"))
      return scene_;
    if (auto n = f_.string("/name")) scene_.name = *n;
    f_.string("/description");
    readLights();
    std::vector<std::string> environments{environmentModeName(EnvironmentMode::None)};
    readAxis("/environment", allEnvironmentModeNames(), "environment mode", environments, scene_.environmentWhere);
    scene_.environments = parseEnvironmentModes(environments);  // each checked against allEnvironmentModeNames() above
    std::vector<std::string> precisions{precisionName(Precision::Fp32)};
    readAxis("/precision", allPrecisionNames(), "precision", precisions, scene_.precisionWhere);
    scene_.precisions = parsePrecisions(precisions);  // each checked against allPrecisionNames() above
    std::vector<std::string> qualities{qualityName(Quality::High)};
    readAxis("/quality", allQualityNames(), "quality level", qualities, scene_.qualityWhere);
    scene_.qualities = parseQualities(qualities);  // each checked against allQualityNames() above
    std::vector<std::string> targets{targetName(Target::Spirv)};
    readAxis("/targets", allTargetNames(), "target", targets, scene_.targetsWhere, "E-SCENE-TARGET");
    scene_.targets = parseTargets(targets);  // each checked against allTargetNames() above
    if (auto level = f_.string("/optimization"))
      if (isOneOf(*level, {"O0", "O1", "O2"}, "optimization level", "/optimization", "E-SCENE-OPTIMIZATION"))
        parseOptimizationLevel(*level, scene_.optimization);
    if (f_.find("/gltf")) readGltfPart();
    if (f_.find("/materials") && f_.isArray("/materials"))
      for (size_t i = 0; i < f_.find("/materials")->size(); ++i) readMaterial(JsonFields::element("/materials", i));
    if (scene_.materials.empty() && !sink_.hasErrors())
      f_.error("E-SCENE-NO-MATERIALS", f_.valueAt(f_.find("/materials") ? "/materials" : ""),
               "the scene uses no materials: there is nothing to compile",
               "list materials in \"materials\", or name a glTF file whose meshes use some in \"gltf\"");
    return scene_;
  }

 private:
  void readLights() {
    scene_.lightsWhere = f_.valueAt("/lights");
    if (!f_.find("/lights") || !f_.isArray("/lights")) return;
    for (size_t i = 0; i < f_.find("/lights")->size(); ++i) {
      std::string ptr = JsonFields::element("/lights", i);
      if (!f_.object(ptr, {"type"}, {"name"}, "light")) continue;
      auto type = f_.string(ptr + "/type");
      auto name = f_.string(ptr + "/name");
      if (!type) continue;
      if (!isOneOf(*type, allLightTypeNames(), "light type", ptr + "/type", "E-SCENE-LIGHT-TYPE")) continue;
      scene_.lights.push_back({*parseLightType(*type), name.value_or(""), f_.valueAt(ptr + "/type")});
    }
  }

  bool isOneOf(const std::string& v, const std::vector<std::string>& allowed, const std::string& what,
               const std::string& ptr, const std::string& code) {
    if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return true;
    f_.error(code, f_.valueAt(ptr), "unknown " + what + " '" + clipped(v) + "': expected one of " + quotedList(allowed),
             suggest(v, allowed));
    return false;
  }

  // A string, or a non-empty array of distinct strings, each from `allowed`.
  void readAxis(const std::string& ptr, const std::vector<std::string>& allowed, const std::string& what,
                std::vector<std::string>& out, SourceLocation& where, const std::string& code = "E-SCENE-AXIS-VALUE") {
    const json* j = f_.find(ptr);
    where = f_.valueAt(ptr);
    if (!j) return;
    std::vector<std::pair<std::string, std::string>> values;  // value, its pointer
    if (j->is_string()) {
      values.push_back({j->get<std::string>(), ptr});
    } else if (j->is_array() && !j->empty()) {
      for (size_t i = 0; i < j->size(); ++i) {
        std::string e = JsonFields::element(ptr, i);
        if (auto s = f_.string(e)) values.push_back({*s, e});
      }
    } else {
      f_.error("E-FIELD-TYPE", where,
               "'" + JsonFields::describe(ptr) + "' must be a " + what + " or a non-empty array of them, found " +
                   (j->is_array() ? "an empty array" : JsonFields::kindOf(*j)));
      return;
    }
    std::vector<std::string> read;
    for (const auto& [v, at] : values) {
      if (!isOneOf(v, allowed, what, at, code)) continue;
      if (std::find(read.begin(), read.end(), v) != read.end()) {
        f_.error("E-SCENE-DUPLICATE", f_.valueAt(at), what + " '" + v + "' is listed twice");
        continue;
      }
      read.push_back(v);
    }
    // Axis values in their canonical order, so the plan does not depend on how they were listed.
    std::vector<std::string> ordered;
    for (const auto& a : allowed)
      if (std::find(read.begin(), read.end(), a) != read.end()) ordered.push_back(a);
    if (!ordered.empty()) out = ordered;
  }

  void readGltfPart() {
    auto written = f_.string("/gltf");
    if (!written) return;
    SourceLocation at = f_.valueAt("/gltf");
    if (!isGltf(*written)) {
      f_.error("E-UNSUPPORTED-FORMAT", at,
               "\"gltf\" must name a .gltf or .glb file, found '" + clipped(*written) + "'");
      return;
    }
    try {
      GltfSceneContents g = readGltfScene(relativeTo(doc_.file(), *written), lib_);
      scene_.lights.insert(scene_.lights.end(), g.lights.begin(), g.lights.end());
      scene_.warnings.insert(scene_.warnings.end(), g.warnings.begin(), g.warnings.end());
      for (auto& m : g.materials) addMaterial(std::move(m));
      if (!f_.find("/environment") && (g.imageBased || scene_.lights.empty())) {
        scene_.environments = {EnvironmentMode::IblLut};
        if (!g.imageBased) scene_.warnings.push_back(noLightsWarning(at));
      }
    } catch (const DiagnosticError& e) {
      for (const auto& d : e.diagnostics()) sink_.error(d.code, d.where, d.message, d.suggestion);
    }
  }

  void readMaterial(const std::string& ptr) {
    if (!f_.object(ptr, {"file"}, {"material", "uses"}, "scene material")) return;
    auto file = f_.string(ptr + "/file");
    auto pick = f_.string(ptr + "/material");
    if (!file) return;
    std::vector<MaterialDesc> loaded;
    try {
      loaded = loadMaterialFile(relativeTo(doc_.file(), *file), lib_);
    } catch (const DiagnosticError& e) {
      for (const auto& d : e.diagnostics()) {
        // A missing file is reported where the scene names it.
        SourceLocation where = d.code == "E-FILE-NOT-FOUND" ? f_.valueAt(ptr + "/file") : d.where;
        sink_.error(d.code, where, d.message, d.suggestion);
      }
      return;
    }
    if (pick) {
      std::vector<std::string> names;
      for (const auto& m : loaded) names.push_back(m.name);
      auto it = std::find(names.begin(), names.end(), *pick);
      if (it == names.end()) {
        f_.error("E-SCENE-UNKNOWN-MATERIAL", f_.valueAt(ptr + "/material"),
                 "'" + *file + "' has no material '" + clipped(*pick) + "' (it has " + quotedList(names) + ")",
                 suggest(*pick, names));
        return;
      }
      loaded = {loaded[static_cast<size_t>(it - names.begin())]};
    }
    for (auto& m : loaded) {
      SceneMaterial sm;
      sm.where = f_.valueAt(ptr + "/file");
      for (const auto& w : m.warnings) scene_.warnings.push_back(w);
      sm.uses = readUses(f_, ptr + "/uses", m, lib_);
      sm.material = std::move(m);
      addMaterial(std::move(sm));
    }
  }

  // One material listed twice (same name from the same file) is one material with both lists
  // of uses; two different materials of one name would write the same permutation files.
  void addMaterial(SceneMaterial sm) {
    for (auto& have : scene_.materials) {
      if (have.material.name != sm.material.name) continue;
      if (have.material.sourceFile == sm.material.sourceFile) {
        have.uses.insert(have.uses.end(), sm.uses.begin(), sm.uses.end());
      } else {
        f_.error("E-SCENE-DUPLICATE-MATERIAL", sm.where,
                 "material '" + sm.material.name + "' of " + sm.material.sourceFile + " has the name of the one from " +
                     have.material.sourceFile + ": their permutations would be written to the same files",
                 "rename one of them");
      }
      return;
    }
    scene_.materials.push_back(std::move(sm));
  }

  const JsonDocument& doc_;
  const ShaderLibrary& lib_;
  JsonFields f_;
  DiagnosticSink& sink_;
  SceneDesc scene_;
};

SceneDesc loadGltfSceneFile(const std::string& path, const ShaderLibrary& lib) {
  GltfSceneContents g = readGltfScene(path, lib);
  SceneDesc scene;
  scene.file = path;
  scene.name = std::filesystem::path(path).stem().string();
  scene.lights = std::move(g.lights);
  scene.materials = std::move(g.materials);
  scene.warnings = std::move(g.warnings);
  // A glTF file says nothing about precision, quality or targets: fp32, high, spirv; image
  // based light only when the file uses EXT_lights_image_based (docs/scenes.md).
  scene.environments = {g.imageBased || scene.lights.empty() ? EnvironmentMode::IblLut : EnvironmentMode::None};
  if (!g.imageBased && scene.lights.empty()) scene.warnings.push_back(noLightsWarning({path, 1, 1}));
  scene.lightsWhere = scene.environmentWhere = scene.precisionWhere = scene.qualityWhere = scene.targetsWhere =
      SourceLocation(path, 1, 1);
  if (scene.materials.empty())
    throw DiagnosticError({{Severity::Error,
                            "E-SCENE-NO-MATERIALS",
                            {path, 1, 1},
                            "no mesh of the glTF scene uses a material: there is nothing to compile"}});
  return scene;
}

}  // namespace

std::vector<LightType> SceneDesc::lightTypes() const {
  std::vector<LightType> types;
  for (const auto& l : lights) types.push_back(l.type);
  return canonicalLights(types);
}

SceneDesc parseSceneJson(std::string text, const std::string& file, const ShaderLibrary& lib) {
  JsonDocument doc = JsonDocument::parse(std::move(text), file, kMaxSceneJsonDepth, kMaxSceneJsonValues);
  DiagnosticSink sink;
  SceneJsonReader reader(doc, lib, sink);
  SceneDesc scene = reader.run();
  throwInFileOrder(sink, file);
  return scene;
}

SceneDesc loadScene(const std::string& path, const ShaderLibrary& lib) {
  if (isGltf(path)) return loadGltfSceneFile(path, lib);
  if (lowerExtension(path) != ".json")
    throw DiagnosticError({{Severity::Error, "E-UNSUPPORTED-FORMAT", SourceLocation(path, 0, 0),
                            "unsupported scene file extension '" + lowerExtension(path) +
                                "': expected .json (scene JSON), .gltf or .glb (glTF 2.0)"}});
  return parseSceneJson(readMaterialFile(path, input_kind::kScene), path, lib);
}

}  // namespace mb
