// Reading and checking the shading models (models/<name>.json): skeleton and parts, the
// light types and environment modes, features, roles and their default bricks, inputs with
// their defaults and ranges, and the model tables that bind roles to bricks (quality levels,
// incompatible combinations). Runs after the slots and bricks are read (library_loader.cpp),
// since roles name slots and tables name bricks.
#include <algorithm>
#include <set>

#include "core/vocabulary.hpp"
#include "library/library_loader.hpp"
#include "library/value_json.hpp"

namespace mb {

void LibraryLoader::readModel(const std::string& name, const SourceLocation& listedAt) {
  auto doc = loadJson("models/" + name + ".json", listedAt);
  if (!doc) return;
  JsonFields f(*doc, sink_);
  if (!f.object("", {"name", "description", "skeleton", "requires", "lights", "environments", "roles", "inputs"},
                {"features", "parts", "quality", "incompatible", "lightMethods"}, "shading model '" + name + "'"))
    return;
  ShadingModel m;
  m.name = name;
  auto declared = f.string("/name");
  if (declared && *declared != name)
    f.error("E-NAME-MISMATCH", f.valueAt("/name"),
            "model name '" + *declared + "' differs from its file name '" + name + ".json'");
  m.description = f.string("/description").value_or("");
  m.skeleton = readGlsl(f, "/skeleton", "models").value_or("");
  if (f.find("/parts") && f.isArray("/parts"))
    for (size_t i = 0; i < f.find("/parts")->size(); ++i)
      if (auto part = readGlsl(f, JsonFields::element("/parts", i), "models")) m.parts.push_back(*part);
  m.requiredUnits = requiredUnits(f, "/requires");
  m.lights = parseLightTypes(namesFrom(f, "/lights", allLightTypeNames(), "light type"));
  m.environments = parseEnvironmentModes(namesFrom(f, "/environments", allEnvironmentModeNames(), "environment mode"));
  if (f.find("/features")) m.features = readFeatures(f);
  if (f.find("/lightMethods")) m.lightMethods = readLightMethods(f, m);
  m.roles = readRoles(f, m);
  checkRoleMethods(f, m);
  m.inputs = readModelInputs(f, m);
  if (f.find("/quality")) m.quality = readQuality(f, m);
  if (f.find("/incompatible")) m.incompatible = readIncompatible(f, m);
  data_.models.push_back(std::move(m));
}

// One "role": "brick" member of a model table (quality levels, incompatible pairs): the
// role must be the model's and the brick of that role's slot. `what` starts the message.
std::optional<std::string> LibraryLoader::roleBinding(JsonFields& f, const std::string& ptr,
                                                      const std::string& roleName, const ShadingModel& m,
                                                      const std::string& what) {
  auto id = f.string(ptr);
  const ModelRole* role = m.findRole(roleName);
  if (!role) {
    std::vector<std::string> roleNames;
    for (const auto& r : m.roles) roleNames.push_back(r.role);
    f.error("E-UNKNOWN-ROLE", f.keyAt(ptr),
            what + " names unknown role '" + roleName + "': model '" + m.name + "' has " + quotedList(roleNames),
            didYouMean(roleName, roleNames));
    return std::nullopt;
  }
  if (!id) return std::nullopt;
  const Brick* b = findLoadedBrick(*id);
  if (!b || b->slot != role->slot) {
    f.error(
        "E-UNKNOWN-BRICK", f.valueAt(ptr),
        what + " binds '" + *id + "' to role '" + role->role + "', but it is not a brick of slot '" + role->slot + "'",
        didYouMean(*id, loadedBricksOf(role->slot)));
    return std::nullopt;
  }
  return id;
}

// "quality": {"low": {role: brick}, "medium": {...}}. "high" is the default bindings and is
// not written (docs/scenes.md "Quality"): the levels are allQualityNames() but "high".
std::map<std::string, std::map<std::string, std::string>> LibraryLoader::readQuality(JsonFields& f,
                                                                                     const ShadingModel& m) {
  static const std::vector<std::string> levels = [] {
    std::vector<std::string> v = allQualityNames();
    std::erase(v, qualityName(Quality::High));
    return v;
  }();
  std::map<std::string, std::map<std::string, std::string>> out;
  if (!f.object("/quality", {}, levels, "quality table")) return out;
  for (const auto& level : levels) {
    std::string lptr = JsonFields::member("/quality", level);
    if (!f.find(lptr) || !f.isObject(lptr)) continue;
    auto& bindings = out[level];
    for (const auto& item : f.find(lptr)->items())
      if (auto id = roleBinding(f, JsonFields::member(lptr, item.key()), item.key(), m, "quality '" + level + "'"))
        bindings[item.key()] = *id;
  }
  return out;
}

// "incompatible": [{"bricks": {role: brick, ...}, "reason": "..."}] (docs/scenes.md "Axes
// and validity"): brick combinations that make no sense in this model.
std::vector<BrickRule> LibraryLoader::readIncompatible(JsonFields& f, const ShadingModel& m) {
  std::vector<BrickRule> out;
  if (!f.isArray("/incompatible")) return out;
  for (size_t i = 0; i < f.find("/incompatible")->size(); ++i) {
    std::string ptr = JsonFields::element("/incompatible", i);
    if (!f.object(ptr, {"bricks", "reason"}, {}, "incompatible-bricks rule")) continue;
    BrickRule rule;
    rule.reason = f.string(ptr + "/reason").value_or("");
    bool complete = f.isObject(ptr + "/bricks");
    if (complete && f.find(ptr + "/bricks")->empty()) {
      f.error("E-FIELD-TYPE", f.valueAt(ptr + "/bricks"),
              "an incompatible-bricks rule names no bricks: expected role: brick pairs");
      complete = false;
    }
    if (complete)
      for (const auto& item : f.find(ptr + "/bricks")->items()) {
        auto id =
            roleBinding(f, JsonFields::member(ptr + "/bricks", item.key()), item.key(), m, "incompatible-bricks rule");
        if (id)
          rule.bricks.emplace_back(item.key(), *id);
        else
          complete = false;
      }
    if (complete && !rule.reason.empty()) out.push_back(std::move(rule));
  }
  return out;
}

// "lightMethods": [{"light": "sphere", "methods": [...], "default": "...", "quality": {"low":
// "..."}, "description": "..."}] (docs/models.md "Light methods"): the ways the model may shade
// a light type, one of which each permutation picks.
std::vector<LightMethodChoice> LibraryLoader::readLightMethods(JsonFields& f, const ShadingModel& m) {
  static const std::vector<std::string> levels = [] {
    std::vector<std::string> v = allQualityNames();
    std::erase(v, qualityName(Quality::High));
    return v;
  }();
  std::vector<LightMethodChoice> out;
  if (!f.isArray("/lightMethods")) return out;
  for (size_t i = 0; i < f.find("/lightMethods")->size(); ++i) {
    std::string ptr = JsonFields::element("/lightMethods", i);
    if (!f.object(ptr, {"light", "methods", "default", "description"}, {"quality"}, "light method choice")) continue;
    LightMethodChoice c;
    c.description = f.string(ptr + "/description").value_or("");
    auto light = f.string(ptr + "/light");
    LightType type = LightType::Dir;
    bool known = false;
    if (auto parsed = light ? parseLightType(*light) : std::nullopt) {
      type = *parsed;
      known = std::find(m.lights.begin(), m.lights.end(), type) != m.lights.end();
    }
    if (light && !known)
      f.error("E-UNKNOWN-NAME", f.valueAt(ptr + "/light"),
              "light method choice for '" + *light + "', which model '" + m.name + "' does not shade (it shades " +
                  quotedList(lightTypeNames(m.lights)) + ")",
              didYouMean(*light, lightTypeNames(m.lights)));
    if (known && std::any_of(out.begin(), out.end(), [&](const LightMethodChoice& x) { return x.light == type; })) {
      f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/light"), "light '" + *light + "' has two method choices");
      known = false;
    }
    if (auto names = f.strings(ptr + "/methods")) {
      for (size_t k = 0; k < names->size(); ++k) {
        std::string at = JsonFields::element(ptr + "/methods", k);
        if (!isIdentifier((*names)[k]))
          f.error("E-INVALID-NAME", f.valueAt(at),
                  "method name '" + (*names)[k] + "' must match [A-Za-z_][A-Za-z0-9_]*");
        else if (std::find(c.methods.begin(), c.methods.end(), (*names)[k]) != c.methods.end())
          f.error("E-DUPLICATE-NAME", f.valueAt(at), "method '" + (*names)[k] + "' is listed twice");
        else
          c.methods.push_back((*names)[k]);
      }
    }
    auto method = [&](const std::string& at) -> std::optional<std::string> {
      auto name = f.string(at);
      if (!name) return std::nullopt;
      if (std::find(c.methods.begin(), c.methods.end(), *name) == c.methods.end()) {
        f.error("E-UNKNOWN-NAME", f.valueAt(at),
                "unknown method '" + *name + "': expected one of " + quotedList(c.methods),
                didYouMean(*name, c.methods));
        return std::nullopt;
      }
      return name;
    };
    auto chosen = method(ptr + "/default");
    if (f.find(ptr + "/quality") && f.object(ptr + "/quality", {}, levels, "light method quality table"))
      for (const auto& level : levels)
        if (f.find(JsonFields::member(ptr + "/quality", level)))
          if (auto q = method(JsonFields::member(ptr + "/quality", level))) c.quality[level] = *q;
    if (!known || !chosen) continue;
    c.light = type;
    c.defaultMethod = *chosen;
    out.push_back(std::move(c));
  }
  return out;
}

// A role's "method" must be offered for every light the role names.
void LibraryLoader::checkRoleMethods(JsonFields& f, const ShadingModel& m) {
  if (!f.isArray("/roles")) return;
  for (size_t i = 0; i < f.find("/roles")->size(); ++i) {
    std::string ptr = JsonFields::element("/roles", i);
    if (!f.find(ptr + "/method")) continue;
    auto method = f.string(ptr + "/method");
    auto role = f.string(ptr + "/role");
    if (!method || !role) continue;
    const ModelRole* r = m.findRole(*role);
    if (!r || r->method != *method) continue;
    bool offered = !r->lights.empty();
    for (LightType t : r->lights) {
      const LightMethodChoice* c = m.findLightMethod(t);
      offered = offered && c && std::find(c->methods.begin(), c->methods.end(), *method) != c->methods.end();
    }
    if (!offered)
      f.error(
          "E-UNKNOWN-NAME", f.valueAt(ptr + "/method"),
          "role '" + *role + "' has method '" + *method +
              "', which its lights must all offer (the model's lightMethods; a role with a method names its lights)");
  }
}

// A string array whose entries must come from `allowed`, each once.
std::vector<std::string> LibraryLoader::namesFrom(JsonFields& f, const std::string& ptr,
                                                  const std::vector<std::string>& allowed, const std::string& what) {
  std::vector<std::string> out;
  auto names = f.strings(ptr);
  if (!names) return out;
  for (size_t i = 0; i < names->size(); ++i) {
    const std::string& n = (*names)[i];
    std::string at = JsonFields::element(ptr, i);
    if (std::find(allowed.begin(), allowed.end(), n) == allowed.end())
      f.error("E-UNKNOWN-NAME", f.valueAt(at),
              "unknown " + what + " '" + n + "': expected one of " + quotedList(allowed), didYouMean(n, allowed));
    else if (std::find(out.begin(), out.end(), n) != out.end())
      f.error("E-DUPLICATE-NAME", f.valueAt(at), what + " '" + n + "' is listed twice");
    else
      out.push_back(n);
  }
  return out;
}

std::vector<ModelFeature> LibraryLoader::readFeatures(JsonFields& f) {
  std::vector<ModelFeature> out;
  if (!f.isArray("/features")) return out;
  for (size_t i = 0; i < f.find("/features")->size(); ++i) {
    std::string ptr = JsonFields::element("/features", i);
    if (!f.object(ptr, {"name", "description"}, {"file", "requires"}, "model feature")) continue;
    ModelFeature feat;
    auto fname = identifier(f, ptr + "/name", "feature name");
    feat.description = f.string(ptr + "/description").value_or("");
    if (f.find(ptr + "/file")) feat.file = readGlsl(f, ptr + "/file", "models").value_or("");
    if (f.find(ptr + "/requires")) feat.requiredUnits = requiredUnits(f, ptr + "/requires");
    if (!fname) continue;
    if (std::any_of(out.begin(), out.end(), [&](const ModelFeature& x) { return x.name == *fname; })) {
      f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/name"), "feature '" + *fname + "' is listed twice");
      continue;
    }
    feat.name = *fname;
    out.push_back(std::move(feat));
  }
  return out;
}

std::vector<std::string> LibraryLoader::featureNames(const ShadingModel& m) const {
  std::vector<std::string> names;
  for (const auto& x : m.features) names.push_back(x.name);
  return names;
}

// A "feature" member must name a feature of the model.
std::string LibraryLoader::featureRef(JsonFields& f, const std::string& ptr, const ShadingModel& m) {
  if (!f.find(ptr)) return {};
  auto name = f.string(ptr);
  if (!name) return {};
  if (!m.findFeature(*name)) {
    f.error("E-UNKNOWN-NAME", f.valueAt(ptr),
            "unknown feature '" + *name + "': model '" + m.name + "' has " + quotedList(featureNames(m)),
            didYouMean(*name, featureNames(m)));
    return {};
  }
  return *name;
}

std::vector<ModelRole> LibraryLoader::readRoles(JsonFields& f, const ShadingModel& m) {
  std::vector<ModelRole> out;
  if (!f.isArray("/roles")) return out;
  std::vector<std::string> known;
  for (const auto& s : data_.slots) known.push_back(s.name);
  for (size_t i = 0; i < f.find("/roles")->size(); ++i) {
    std::string ptr = JsonFields::element("/roles", i);
    if (!f.object(ptr, {"role", "slot", "description"},
                  {"default", "feature", "lights", "environments", "method", "toleranceScale"}, "model role"))
      continue;
    ModelRole r;
    auto role = identifier(f, ptr + "/role", "role name");
    auto slot = f.string(ptr + "/slot");
    r.description = f.string(ptr + "/description").value_or("");
    r.feature = featureRef(f, ptr + "/feature", m);
    if (f.find(ptr + "/method")) r.method = f.string(ptr + "/method").value_or("");
    if (f.find(ptr + "/toleranceScale") &&
        f.object(ptr + "/toleranceScale", {"factor", "reason"}, {}, "role tolerance scale")) {
      auto factor = f.number(ptr + "/toleranceScale/factor");
      if (factor && !(*factor >= 1.0 && *factor <= 1e6))
        f.error("E-OUT-OF-RANGE", f.valueAt(ptr + "/toleranceScale/factor"),
                "a role's tolerance scale must lie in [1, 1e6]: it says how much more than the light's irradiance "
                "multiplies the role's result");
      else if (factor)
        r.toleranceScale = *factor;
      r.toleranceReason = f.string(ptr + "/toleranceScale/reason").value_or("");
    }
    if (f.find(ptr + "/lights"))
      r.lights = parseLightTypes(namesFrom(f, ptr + "/lights", lightTypeNames(m.lights), "light type"));
    if (f.find(ptr + "/environments"))
      r.environments = parseEnvironmentModes(
          namesFrom(f, ptr + "/environments", environmentModeNames(m.environments), "environment mode"));
    if (slot && std::find(known.begin(), known.end(), *slot) == known.end()) {
      f.error("E-UNKNOWN-SLOT", f.valueAt(ptr + "/slot"),
              "unknown slot '" + *slot + "': the manifest's slots are " + quotedList(known), didYouMean(*slot, known));
      slot.reset();
    }
    if (slot && f.find(ptr + "/default")) {
      auto id = f.string(ptr + "/default");
      const Brick* b = id ? findLoadedBrick(*id) : nullptr;
      if (id && (!b || b->slot != *slot)) {
        f.error("E-UNKNOWN-BRICK", f.valueAt(ptr + "/default"),
                "default '" + *id + "' is not a brick of slot '" + *slot + "'", didYouMean(*id, loadedBricksOf(*slot)));
      } else if (id) {
        r.defaultBrick = *id;
      }
    }
    if (role && std::any_of(out.begin(), out.end(), [&](const ModelRole& x) { return x.role == *role; })) {
      f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/role"), "role '" + *role + "' is listed twice");
      continue;
    }
    if (!role || !slot) continue;
    r.role = *role;
    r.slot = *slot;
    out.push_back(std::move(r));
  }
  return out;
}

const Brick* LibraryLoader::findLoadedBrick(const std::string& id) const {
  for (const auto& b : data_.bricks)
    if (b.id == id) return &b;
  return nullptr;
}

std::vector<std::string> LibraryLoader::loadedBricksOf(const std::string& slot) const {
  std::vector<std::string> ids;
  for (const auto& b : data_.bricks)
    if (b.slot == slot) ids.push_back(b.id);
  return ids;
}

std::vector<ModelInput> LibraryLoader::readModelInputs(JsonFields& f, const ShadingModel& m) {
  std::vector<ModelInput> inputs;
  if (!f.isArray("/inputs")) return inputs;
  std::set<std::string> seen;
  for (size_t i = 0; i < f.find("/inputs")->size(); ++i) {
    std::string ptr = JsonFields::element("/inputs", i);
    if (!f.object(ptr, {"name", "type", "default", "range", "description"}, {"feature", "neutral", "roughness"},
                  "model input"))
      continue;
    ModelInput in;
    auto name = identifier(f, ptr + "/name", "input name");
    auto type = valueType(f, ptr + "/type", false);
    auto r = range(f, ptr + "/range");
    in.description = f.string(ptr + "/description").value_or("");
    in.feature = featureRef(f, ptr + "/feature", m);
    // Check the default as far as the other fields allow, so one run shows every error.
    std::optional<std::vector<double>> value;
    if (type) value = readTypedValue(f, ptr + "/default", *type);
    if (value && r) checkInRange(f, ptr + "/default", *value, *r, "the input's range");
    if (type && f.find(ptr + "/neutral")) {
      auto neutral = readTypedValue(f, ptr + "/neutral", *type);
      if (neutral && r) checkInRange(f, ptr + "/neutral", *neutral, *r, "the input's range");
      if (neutral) in.neutral = *neutral;
    }
    if (name && !seen.insert(*name).second) {
      f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/name"), "input '" + *name + "' is listed twice");
      continue;
    }
    if (name) in.roughness = readRoughnessKind(f, ptr, *name, type);
    if (!name || !type || !r || !value) continue;
    in.name = *name;
    in.type = *type;
    in.range = *r;
    in.defaultValue = *value;
    inputs.push_back(std::move(in));
  }
  return inputs;
}

}  // namespace mb
