// The bricks glTF import binds, read from the file the manifest's "gltf_defaults" names
// (docs/formats.md "gltf_defaults.json"): the model glTF materials map to, the bindings of
// every material and those of each feature. Read after the models, since each binding names
// a role of the model and a brick of that role's slot.
#include <algorithm>
#include <filesystem>
#include <set>

#include "library/library_loader.hpp"
#include "library/value_json.hpp"

namespace mb {

namespace fs = std::filesystem;

void LibraryLoader::readGltfDefaults(JsonFields& manifest) {
  if (!manifest.find("/gltf_defaults")) return;
  auto file = manifest.string("/gltf_defaults");
  if (!file) return;
  SourceLocation listedAt = manifest.valueAt("/gltf_defaults");
  std::string rel = fs::path(*file).lexically_normal().generic_string();
  if (fs::path(*file).is_absolute() || rel.rfind("..", 0) == 0 || rel.empty() || rel == ".") {
    manifest.error("E-INVALID-PATH", listedAt, "'" + *file + "' must be a relative path inside the shader library");
    return;
  }
  auto doc = loadJson(rel, listedAt);
  if (!doc) return;
  JsonFields f(*doc, sink_);
  if (!f.object("", {"schema", "model", "always", "features"}, {}, "the glTF defaults")) return;
  auto schema = f.number("/schema");
  if (schema && *schema != 1)
    f.error("E-SCHEMA-VERSION", f.valueAt("/schema"),
            "unsupported glTF defaults schema " + formatNumber(*schema) + ": expected 1");
  auto modelName = f.string("/model");
  if (!modelName) return;
  auto model = std::find_if(data_.models.begin(), data_.models.end(),
                            [&](const ShadingModel& m) { return m.name == *modelName; });
  if (model == data_.models.end()) {
    std::vector<std::string> names;
    for (const auto& m : data_.models) names.push_back(m.name);
    f.error("E-UNKNOWN-NAME", f.valueAt("/model"),
            "unknown model '" + *modelName + "': the library has " + quotedList(names), didYouMean(*modelName, names));
    return;
  }
  GltfDefaults out;
  out.file = rel;
  out.model = *modelName;
  if (f.object("/always", {"why", "bricks"}, {}, "'always'")) {
    nonEmpty(f, "/always/why");
    out.always = readGltfBindings(f, "/always/bricks", *model, "");
  }
  if (f.isArray("/features")) {
    for (size_t i = 0; i < f.find("/features")->size(); ++i) {
      std::string ptr = JsonFields::element("/features", i);
      if (!f.object(ptr, {"feature", "why", "bricks"}, {}, "glTF feature defaults")) continue;
      nonEmpty(f, ptr + "/why");
      std::string feature = featureRef(f, ptr + "/feature", *model);
      if (feature.empty()) continue;
      if (out.features.count(feature)) {
        f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/feature"), "feature '" + feature + "' is listed twice");
        continue;
      }
      out.features[feature] = readGltfBindings(f, ptr + "/bricks", *model, feature);
    }
  }
  data_.gltfDefaults = std::move(out);
}

// [{"role", "brick"}]: each role a role of the model that exists exactly when `feature` is
// enabled (every material's roles when it is empty), bound once, to a brick of its slot.
std::vector<GltfBinding> LibraryLoader::readGltfBindings(JsonFields& f, const std::string& ptr, const ShadingModel& m,
                                                         const std::string& feature) {
  std::vector<GltfBinding> out;
  if (!f.isArray(ptr)) return out;
  std::set<std::string> seen;
  for (size_t i = 0; i < f.find(ptr)->size(); ++i) {
    std::string eptr = JsonFields::element(ptr, i);
    if (!f.object(eptr, {"role", "brick"}, {}, "glTF binding")) continue;
    auto roleName = f.string(eptr + "/role");
    auto id = f.string(eptr + "/brick");
    if (!roleName || !id) continue;
    const ModelRole* role = m.findRole(*roleName);
    if (!role) {
      std::vector<std::string> roleNames;
      for (const auto& r : m.roles) roleNames.push_back(r.role);
      f.error("E-UNKNOWN-ROLE", f.valueAt(eptr + "/role"),
              "unknown role '" + *roleName + "': model '" + m.name + "' has " + quotedList(roleNames),
              didYouMean(*roleName, roleNames));
      continue;
    }
    if (role->feature != feature) {
      f.error("E-INVALID-VALUE", f.valueAt(eptr + "/role"),
              "role '" + *roleName + "' " +
                  (role->feature.empty() ? "exists without a feature: bind it in 'always'"
                                         : "exists only with feature '" + role->feature + "': bind it there") +
                  (feature.empty() ? "" : ", not under feature '" + feature + "'"));
      continue;
    }
    if (!seen.insert(*roleName).second) {
      f.error("E-DUPLICATE-NAME", f.valueAt(eptr + "/role"), "role '" + *roleName + "' is bound twice");
      continue;
    }
    const Brick* b = findLoadedBrick(*id);
    if (!b || b->slot != role->slot) {
      f.error("E-UNKNOWN-BRICK", f.valueAt(eptr + "/brick"),
              "'" + *id + "' is not a brick of slot '" + role->slot + "' (role '" + *roleName + "' of model '" +
                  m.name + "')",
              didYouMean(*id, loadedBricksOf(role->slot)));
      continue;
    }
    out.push_back({*roleName, *id});
  }
  return out;
}

}  // namespace mb
