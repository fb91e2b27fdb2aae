// glTF scene reading: walks the nodes of the file's scene (glTF 2.0 spec, "Scenes" and
// "Nodes and Hierarchy") and collects KHR_lights_punctual lights (KHR_lights_punctual spec:
// node.extensions.KHR_lights_punctual.light indexes extensions.KHR_lights_punctual.lights)
// and the materials of the meshes' primitives.
#include "load/scene_gltf.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include "core/json_fields.hpp"
#include "load/gltf_container.hpp"
#include "load/gltf_import.hpp"
#include "load/material_resolve.hpp"

namespace mb {

namespace {

using nlohmann::json;

class GltfSceneWalker {
 public:
  GltfSceneWalker(const JsonDocument& doc, DiagnosticSink& sink) : f_(doc, sink) {}

  // Node indices of the scene, depth first; "scene" (default 0) picks the scene, and a file
  // without scenes contributes every node (the spec leaves that case to the application).
  void walk() {
    if (!f_.isObject("")) return;
    visited_.assign(count("/nodes"), false);
    if (f_.find("/scenes") && f_.isArray("/scenes") && !f_.find("/scenes")->empty()) {
      size_t s = 0;
      if (f_.find("/scene")) s = index(f_.find("/scene"), "/scene", f_.find("/scenes")->size());
      if (s == kBad) return;
      std::string nodes = JsonFields::member(JsonFields::element("/scenes", s), "nodes");
      if (f_.find(nodes) && f_.isArray(nodes))
        for (size_t i = 0; i < f_.find(nodes)->size(); ++i) visitRef(JsonFields::element(nodes, i));
    } else if (f_.find("/nodes") && f_.isArray("/nodes")) {
      for (size_t i = 0; i < f_.find("/nodes")->size(); ++i) visit(i);
    }
  }

  std::vector<std::pair<size_t, SourceLocation>> lightRefs;  // light index, where a node names it
  std::set<size_t> materials;
  std::vector<SourceLocation> defaultMaterialUses;

 private:
  static constexpr size_t kBad = static_cast<size_t>(-1);

  size_t index(const json* j, const std::string& ptr, size_t count) {
    if (!j->is_number_unsigned() || j->get<size_t>() >= count) {
      f_.error("E-GLTF-INDEX", f_.valueAt(ptr),
               "'" + JsonFields::describe(ptr) + "' must be an index below " + std::to_string(count));
      return kBad;
    }
    return j->get<size_t>();
  }

  size_t count(const std::string& ptr) { return f_.find(ptr) && f_.find(ptr)->is_array() ? f_.find(ptr)->size() : 0; }

  void visitRef(const std::string& ptr) {
    size_t n = index(f_.find(ptr), ptr, count("/nodes"));
    if (n != kBad) visit(n);
  }

  void visit(size_t node) {
    if (visited_[node]) return;  // a node listed twice, or a cycle
    visited_[node] = true;
    std::string ptr = JsonFields::element("/nodes", node);
    if (!f_.isObject(ptr)) return;
    std::string light = ptr + "/extensions/KHR_lights_punctual/light";
    if (const json* l = f_.find(light)) {
      size_t i = index(l, light, count("/extensions/KHR_lights_punctual/lights"));
      if (i != kBad) lightRefs.push_back({i, f_.valueAt(light)});
    }
    if (const json* m = f_.find(ptr + "/mesh")) {
      size_t mesh = index(m, ptr + "/mesh", count("/meshes"));
      if (mesh != kBad) visitMesh(mesh);
    }
    std::string children = ptr + "/children";
    if (f_.find(children) && f_.isArray(children))
      for (size_t i = 0; i < f_.find(children)->size(); ++i) visitRef(JsonFields::element(children, i));
  }

  void visitMesh(size_t mesh) {
    std::string prims = JsonFields::member(JsonFields::element("/meshes", mesh), "primitives");
    if (!f_.find(prims) || !f_.isArray(prims)) return;
    for (size_t i = 0; i < f_.find(prims)->size(); ++i) {
      std::string mat = JsonFields::member(JsonFields::element(prims, i), "material");
      if (const json* m = f_.find(mat)) {
        size_t k = index(m, mat, count("/materials"));
        if (k != kBad) materials.insert(k);
      } else {
        defaultMaterialUses.push_back(f_.valueAt(JsonFields::element(prims, i)));
      }
    }
  }

  JsonFields f_;
  std::vector<bool> visited_;  // per node: a bit, not a set's ~48 bytes (a scene may have millions)
};

// KHR_lights_punctual types -> ours (the extension has exactly these three).
std::optional<LightType> lightType(const std::string& t) {
  if (t == "directional") return LightType::Dir;
  if (t == "point") return LightType::Point;
  if (t == "spot") return LightType::Spot;
  return std::nullopt;
}

// KHR_lights_punctual has no area lights. A light's extras may say that it stands for one
// (docs/gltf.md "Area lights"):
//   "extras": {"matbricks_area_light": {"shape": "rect" | "disk", "size": [x, y]}}
// a rectangle of x by y, or a disk (ellipse) of those diameters, in the node's local x-y plane,
// centred on the node and emitting towards its -z (where a spot light points); `intensity` is
// then its luminance in nits. A reader without the convention sees the light's own type, so a
// spot light is the closest fallback; a directional light has no position to stand for one.
// nullopt: no such extras (or an error, reported to `f`'s sink).
std::optional<LightType> areaLightType(JsonFields& f, const std::string& light, const std::string& type) {
  const std::string ptr = JsonFields::member(JsonFields::member(light, "extras"), "matbricks_area_light");
  if (!f.find(ptr)) return std::nullopt;
  if (!f.object(ptr, {"shape", "size"}, {}, "matbricks_area_light")) return std::nullopt;
  const auto shape = f.string(JsonFields::member(ptr, "shape"));
  std::optional<LightType> ours;
  if (shape == "rect") ours = LightType::Rect;
  if (shape == "disk") ours = LightType::Disk;
  if (shape && !ours)
    f.error("E-SCENE-AREA-LIGHT", f.valueAt(JsonFields::member(ptr, "shape")),
            "unknown area light shape '" + clipped(*shape) + "': expected 'rect' or 'disk'",
            suggest(*shape, {"rect", "disk"}));
  const std::string size = JsonFields::member(ptr, "size");
  const nlohmann::json* s = f.find(size);
  if (s) {
    bool ok = s->is_array() && s->size() == 2;
    for (size_t k = 0; ok && k < 2; ++k) ok = (*s)[k].is_number() && (*s)[k].get<double>() > 0.0;
    if (!ok) f.error("E-SCENE-AREA-LIGHT", f.valueAt(size), "area light size must be two positive numbers [x, y]");
  }
  if (type == "directional") {
    f.error("E-SCENE-AREA-LIGHT", f.valueAt(ptr),
            "a directional light cannot stand for an area light (it has no position): make it a spot or point light");
    return std::nullopt;
  }
  return ours;
}

}  // namespace

GltfSceneContents readGltfScene(const std::string& path, const ShaderLibrary& lib) {
  GltfContainerInfo container;
  JsonDocument doc = loadGltfSceneJson(path, container);
  DiagnosticSink sink;
  GltfSceneWalker walker(doc, sink);
  walker.walk();
  JsonFields f(doc, sink);
  GltfSceneContents out;
  for (const auto& [i, where] : walker.lightRefs) {
    std::string ptr = JsonFields::element("/extensions/KHR_lights_punctual/lights", i);
    if (!f.object(ptr, {"type"}, {"name", "color", "intensity", "range", "spot", "extensions", "extras"},
                  "KHR_lights_punctual light"))
      continue;
    auto type = f.string(ptr + "/type");
    if (!type) continue;
    std::optional<LightType> ours = lightType(*type);
    if (!ours) {
      f.error(
          "E-SCENE-LIGHT-TYPE", f.valueAt(ptr + "/type"),
          "unknown KHR_lights_punctual light type '" + clipped(*type) + "': expected 'directional', 'point' or 'spot'",
          suggest(*type, {"directional", "point", "spot"}));
      continue;
    }
    if (std::optional<LightType> area = areaLightType(f, ptr, *type)) ours = area;
    out.lights.push_back({*ours, f.string(ptr + "/name").value_or(""), f.valueAt(ptr + "/type")});
  }
  for (const auto& where : walker.defaultMaterialUses)
    out.warnings.push_back({Severity::Warning, "W-SCENE-GLTF-DEFAULT-MATERIAL", where,
                            "a mesh primitive has no material (glTF's default material): it is not compiled"});
  auto used = f.strings("/extensionsUsed").value_or(std::vector<std::string>{});
  out.imageBased = std::find(used.begin(), used.end(), "EXT_lights_image_based") != used.end();
  sink.throwIfErrors();

  std::vector<GltfMaterial> all = mapGltfDocument(doc, lib, &container);
  for (auto& m : all) {
    if (!walker.materials.count(static_cast<size_t>(m.index))) continue;
    SceneMaterial sm;
    sm.material = resolveMaterialInto(m.source, lib, sink);
    sm.where = m.source.name.where;
    MaterialUse implicit;  // the glTF factors are the material's constants: one use at them
    implicit.where = sm.where;
    sm.uses.push_back(implicit);
    out.materials.push_back(std::move(sm));
    out.warnings.insert(out.warnings.end(), m.source.warnings.begin(), m.source.warnings.end());
  }
  throwInFileOrder(sink, path);
  return out;
}

}  // namespace mb
