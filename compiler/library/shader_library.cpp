#include "library/shader_library.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include "core/data_dir.hpp"
#include "core/json_fields.hpp"
#include "library/value_json.hpp"

namespace mb {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Everything load() collects before it is moved into a ShaderLibrary.
struct LibraryData {
  std::vector<Unit> units;
  std::vector<Slot> slots;
  std::vector<Brick> bricks;
  std::vector<ShadingModel> models;
  std::map<std::string, std::string> sources;  // relative file -> text
};

std::optional<std::string> readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// True if `text` contains `name(` with `name` not part of a longer identifier: enough to
// tell that a brick file defines (or at least mentions as a call) its function.
bool mentionsFunction(const std::string& text, const std::string& name) {
  auto isIdent = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t pos = text.find(name); pos != std::string::npos; pos = text.find(name, pos + 1)) {
    if (pos > 0 && isIdent(text[pos - 1])) continue;
    size_t after = pos + name.size();
    while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
    if (after < text.size() && text[after] == '(') return true;
  }
  return false;
}

// Loads the library's JSON files and checks them. Every problem goes to the sink; the
// caller throws once at the end, so one run reports all mistakes of a new brick.
class LibraryLoader {
 public:
  LibraryLoader(fs::path root, DiagnosticSink& sink) : root_(std::move(root)), sink_(sink) {}

  LibraryData run() {
    auto manifest = loadJson("manifest.json", {});
    if (!manifest) return std::move(data_);
    JsonFields f(*manifest, sink_);
    if (!f.object("", {"schema", "units", "slots", "models"}, {}, "the library manifest"))
      return std::move(data_);
    checkSchema(f);
    readUnits(f);
    forEachName(f, "/slots", "slot", [&](const std::string& n, const SourceLocation& at) {
      readSlot(n, at);
    });
    forEachName(f, "/models", "model", [&](const std::string& n, const SourceLocation& at) {
      readModel(n, at);
    });
    return std::move(data_);
  }

 private:
  // --- files -------------------------------------------------------------------------

  std::string diskPath(const std::string& relative) const {
    return (root_ / relative).lexically_normal().string();
  }

  // Parses root/<relative>. A missing file is reported at `referencedFrom` (the manifest
  // entry that names it) when there is one.
  std::optional<JsonDocument> loadJson(const std::string& relative,
                                       const SourceLocation& referencedFrom) {
    std::string path = diskPath(relative);
    auto text = readFile(path);
    if (!text) {
      SourceLocation at = referencedFrom.file.empty() ? SourceLocation{path, 0, 0} : referencedFrom;
      sink_.error("E-FILE-NOT-FOUND", at, "cannot read library file '" + path + "'");
      return std::nullopt;
    }
    try {
      return JsonDocument::parse(*text, path);
    } catch (const DiagnosticError& e) {
      for (const auto& d : e.diagnostics()) sink_.error(d.code, d.where, d.message, d.suggestion);
      return std::nullopt;
    }
  }

  // Resolves a GLSL path given relative to `baseDir` (a folder under the root) to a path
  // relative to the root, reads it once, and reports it at `ptr` when it is missing.
  std::optional<std::string> readGlsl(JsonFields& f, const std::string& ptr,
                                      const std::string& baseDir) {
    auto file = f.string(ptr);
    if (!file) return std::nullopt;
    fs::path p = fs::path(*file);
    std::string rel = (fs::path(baseDir) / p).lexically_normal().generic_string();
    if (p.is_absolute() || rel.rfind("..", 0) == 0) {
      f.error("E-INVALID-PATH", f.valueAt(ptr),
              "'" + *file + "' must be a relative path inside the shader library");
      return std::nullopt;
    }
    if (!data_.sources.count(rel)) {
      auto text = readFile(root_ / rel);
      if (!text) {
        f.error("E-FILE-NOT-FOUND", f.valueAt(ptr),
                "GLSL file '" + *file + "' not found (looked for '" + diskPath(rel) + "')");
        return std::nullopt;
      }
      data_.sources.emplace(rel, std::move(*text));
    }
    return rel;
  }

  // --- manifest ----------------------------------------------------------------------

  void checkSchema(JsonFields& f) {
    auto schema = f.number("/schema");
    if (schema && *schema != 1)
      f.error("E-SCHEMA-VERSION", f.valueAt("/schema"),
              "unsupported library schema " + formatNumber(*schema) + ": expected 1");
  }

  void readUnits(JsonFields& f) {
    if (!f.isArray("/units")) return;
    std::set<std::string> seen;
    for (size_t i = 0; i < f.find("/units")->size(); ++i) {
      std::string ptr = JsonFields::element("/units", i);
      if (!f.object(ptr, {"id", "file"}, {}, "unit")) continue;
      auto id = identifier(f, ptr + "/id", "unit id");
      auto file = readGlsl(f, ptr + "/file", "");
      if (!id || !file) continue;
      if (!seen.insert(*id).second) {
        f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/id"), "unit '" + *id + "' is listed twice");
        continue;
      }
      data_.units.push_back({*id, *file});
    }
  }

  // Calls `fn` for each distinct identifier in the string array at `ptr`.
  template <class Fn>
  void forEachName(JsonFields& f, const std::string& ptr, const std::string& what, Fn fn) {
    auto names = f.strings(ptr);
    if (!names) return;
    std::set<std::string> seen;
    for (size_t i = 0; i < names->size(); ++i) {
      std::string at = JsonFields::element(ptr, i);
      const std::string& name = (*names)[i];
      if (!isIdentifier(name)) {
        f.error("E-INVALID-NAME", f.valueAt(at),
                what + " name '" + name + "' must match [A-Za-z_][A-Za-z0-9_]*");
        continue;
      }
      if (!seen.insert(name).second) {
        f.error("E-DUPLICATE-NAME", f.valueAt(at), what + " '" + name + "' is listed twice");
        continue;
      }
      fn(name, f.valueAt(at));
    }
  }

  // --- shared field readers -----------------------------------------------------------

  std::optional<std::string> identifier(JsonFields& f, const std::string& ptr,
                                        const std::string& what) {
    auto s = f.string(ptr);
    if (s && !isIdentifier(*s)) {
      f.error("E-INVALID-NAME", f.valueAt(ptr),
              what + " '" + *s + "' must match [A-Za-z_][A-Za-z0-9_]*");
      return std::nullopt;
    }
    return s;
  }

  // A string that must say something (citations, tolerance reasons): the manifest is the
  // only place a reader learns why a formula or a tolerance is what it is.
  std::optional<std::string> nonEmpty(JsonFields& f, const std::string& ptr) {
    auto s = f.string(ptr);
    if (s && s->find_first_not_of(" \t\r\n") == std::string::npos) {
      f.error("E-EMPTY-FIELD", f.valueAt(ptr),
              "'" + JsonFields::describe(ptr) + "' must not be empty");
      return std::nullopt;
    }
    return s;
  }

  std::optional<ValueType> valueType(JsonFields& f, const std::string& ptr, bool allowGeometry) {
    auto s = f.string(ptr);
    if (!s) return std::nullopt;
    std::vector<std::string> allowed = {"float", "vec2", "vec3"};
    if (allowGeometry) allowed.push_back("Geometry");
    auto t = parseValueType(*s);
    if (!t || (*t == ValueType::Geometry && !allowGeometry)) {
      f.error("E-UNKNOWN-TYPE", f.valueAt(ptr),
              "unknown type '" + *s + "' for '" + JsonFields::describe(ptr) + "': expected one of " +
                  quotedList(allowed),
              didYouMean(*s, allowed));
      return std::nullopt;
    }
    return t;
  }

  std::optional<Range> range(JsonFields& f, const std::string& ptr) {
    auto r = f.range(ptr);
    if (!r) return std::nullopt;
    return Range{r->first, r->second};
  }

  // Each entry of the unit-id array at `ptr` must name a unit of the manifest.
  std::vector<std::string> requiredUnits(JsonFields& f, const std::string& ptr) {
    auto ids = f.strings(ptr);
    if (!ids) return {};
    std::vector<std::string> known;
    for (const auto& u : data_.units) known.push_back(u.id);
    for (size_t i = 0; i < ids->size(); ++i) {
      if (std::find(known.begin(), known.end(), (*ids)[i]) != known.end()) continue;
      f.error("E-UNKNOWN-UNIT", f.valueAt(JsonFields::element(ptr, i)),
              "unknown unit '" + (*ids)[i] + "': the manifest's units are " + quotedList(known),
              didYouMean((*ids)[i], known));
    }
    return *ids;
  }

  // --- slots and bricks ----------------------------------------------------------------

  void readSlot(const std::string& folder, const SourceLocation& listedAt) {
    auto doc = loadJson(folder + "/slot.json", listedAt);
    if (!doc) return;
    JsonFields f(*doc, sink_);
    if (!f.object("", {"name", "description", "returns", "params", "bricks"}, {},
                  "slot '" + folder + "'"))
      return;
    Slot slot;
    slot.name = folder;
    auto name = f.string("/name");
    if (name && *name != folder)
      f.error("E-NAME-MISMATCH", f.valueAt("/name"),
              "slot name '" + *name + "' differs from its folder '" + folder +
                  "': the folder name is the slot's id");
    slot.description = f.string("/description").value_or("");
    slot.returns = valueType(f, "/returns", false).value_or(ValueType::Float);
    slot.params = readSlotParams(f);
    data_.slots.push_back(slot);
    if (!f.isArray("/bricks")) return;
    for (size_t i = 0; i < f.find("/bricks")->size(); ++i)
      readBrick(f, JsonFields::element("/bricks", i), slot);
  }

  std::vector<SlotParam> readSlotParams(JsonFields& f) {
    std::vector<SlotParam> params;
    if (!f.isArray("/params")) return params;
    std::set<std::string> seen;
    for (size_t i = 0; i < f.find("/params")->size(); ++i) {
      std::string ptr = JsonFields::element("/params", i);
      if (!f.object(ptr, {"name", "type"}, {}, "slot parameter")) continue;
      auto name = identifier(f, ptr + "/name", "parameter name");
      auto type = valueType(f, ptr + "/type", true);
      if (name && !seen.insert(*name).second)
        f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/name"),
                "parameter '" + *name + "' is listed twice");
      if (name && type) params.push_back({*name, *type});
    }
    return params;
  }

  void readBrick(JsonFields& f, const std::string& ptr, const Slot& slot) {
    const json* idValue = f.find(ptr + "/id");
    std::string what = idValue && idValue->is_string()
                           ? "brick '" + idValue->get<std::string>() + "'"
                           : "brick";
    if (!f.object(ptr,
                  {"id", "name", "function", "file", "citation", "requires", "domain", "tolerance"},
                  {"geometry", "notes", "unstable_variant"}, what))
      return;
    Brick b;
    b.slot = slot.name;
    b.id = brickId(f, ptr + "/id").value_or("");
    b.name = nonEmpty(f, ptr + "/name").value_or("");
    b.function = identifier(f, ptr + "/function", "function name").value_or("");
    b.citation = nonEmpty(f, ptr + "/citation").value_or("");
    b.notes = f.string(ptr + "/notes").value_or("");
    b.requiredUnits = requiredUnits(f, ptr + "/requires");
    if (auto file = readGlsl(f, ptr + "/file", slot.name)) {
      b.file = *file;
      if (!b.function.empty() && !mentionsFunction(data_.sources.at(b.file), b.function))
        f.error("E-MISSING-FUNCTION", f.valueAt(ptr + "/function"),
                "function '" + b.function + "' is not defined in '" + b.file + "'");
    }
    readUnstableVariant(f, ptr + "/unstable_variant", slot, b);
    b.domain = readDomain(f, ptr + "/domain", slot);
    b.geometry = readGeometry(f, ptr + "/geometry", slot);
    b.tolerance = readTolerance(f, ptr + "/tolerance");
    data_.bricks.push_back(std::move(b));
  }

  // The naive form a stability fix replaced, kept so validation can show the problem the
  // fix solves: {"file": GLSL defining the same function, "problem": what goes wrong}.
  void readUnstableVariant(JsonFields& f, const std::string& ptr, const Slot& slot, Brick& b) {
    if (!f.find(ptr)) return;
    if (!f.object(ptr, {"file", "problem"}, {}, "unstable_variant")) return;
    b.unstableProblem = nonEmpty(f, ptr + "/problem").value_or("");
    if (auto file = readGlsl(f, ptr + "/file", slot.name)) {
      b.unstableFile = *file;
      if (!b.function.empty() && !mentionsFunction(data_.sources.at(*file), b.function))
        f.error("E-MISSING-FUNCTION", f.valueAt(ptr + "/file"),
                "function '" + b.function + "' is not defined in '" + *file + "'");
    }
  }

  // Brick ids are global (a material names a brick without its slot), so they must be
  // unique across all slots.
  std::optional<std::string> brickId(JsonFields& f, const std::string& ptr) {
    auto id = identifier(f, ptr, "brick id");
    if (!id) return std::nullopt;
    SourceLocation here = f.valueAt(ptr);
    auto [it, inserted] = brickIdLocations_.emplace(*id, here);
    if (!inserted) {
      const SourceLocation& first = it->second;
      f.error("E-DUPLICATE-BRICK", here,
              "duplicate brick id '" + *id + "': already defined at " + first.file + ":" +
                  std::to_string(first.line) + ":" + std::to_string(first.column));
    }
    return id;
  }

  // The domain is the region validation samples; every scalar/vector parameter needs one,
  // and nothing else may have one (a typo there would silently leave a parameter unsampled).
  std::map<std::string, Range> readDomain(JsonFields& f, const std::string& ptr, const Slot& slot) {
    std::map<std::string, Range> domain;
    if (!f.isObject(ptr)) return domain;
    std::vector<std::string> sampled;
    for (const auto& p : slot.params)
      if (p.type != ValueType::Geometry) sampled.push_back(p.name);
    for (const auto& [key, value] : f.find(ptr)->items()) {
      std::string at = JsonFields::member(ptr, key);
      if (std::find(sampled.begin(), sampled.end(), key) == sampled.end()) {
        f.error("E-UNKNOWN-PARAM", f.keyAt(at),
                "domain names '" + key + "', which is not a float/vec2/vec3 parameter of slot '" +
                    slot.name + "' (those are " + quotedList(sampled) + ")",
                didYouMean(key, sampled));
        continue;
      }
      if (auto r = range(f, at)) domain[key] = *r;
    }
    for (const auto& name : sampled) {
      if (!f.find(ptr)->contains(name))
        f.error("E-MISSING-DOMAIN", f.valueAt(ptr),
                "domain has no range for parameter '" + name + "' of slot '" + slot.name +
                    "': every float/vec2/vec3 parameter needs one");
    }
    return domain;
  }

  GeometryDomain readGeometry(JsonFields& f, const std::string& ptr, const Slot& slot) {
    GeometryDomain g;
    if (!f.find(ptr)) return g;
    bool hasGeometry = std::any_of(slot.params.begin(), slot.params.end(),
                                   [](const SlotParam& p) { return p.type == ValueType::Geometry; });
    if (!hasGeometry) {
      f.error("E-UNKNOWN-PARAM", f.keyAt(ptr),
              "'geometry' domain given, but slot '" + slot.name + "' has no Geometry parameter");
      return g;
    }
    if (!f.object(ptr, {}, {"NoV", "NoL"}, "geometry domain")) return g;
    auto cosine = [&](const std::string& key, Range& out) {
      std::string at = JsonFields::member(ptr, key);
      auto r = range(f, at);
      if (!r) return;
      // Signed cosines are allowed: wrap lighting samples light from behind (n.l < 0).
      if (r->lo < -1.0 || r->hi > 1.0)
        f.error("E-PARAM-RANGE", f.valueAt(at),
                "'" + JsonFields::describe(at) + "' must lie inside [-1, 1]: it bounds a cosine");
      else
        out = *r;
    };
    cosine("NoV", g.NoV);
    cosine("NoL", g.NoL);
    return g;
  }

  Tolerance readTolerance(JsonFields& f, const std::string& ptr) {
    Tolerance t;
    if (!f.object(ptr, {"abs", "rel", "reason"}, {}, "tolerance")) return t;
    auto bound = [&](const std::string& key, double& out) {
      std::string at = JsonFields::member(ptr, key);
      auto v = f.number(at);
      if (!v) return;
      if (!(std::isfinite(*v) && *v >= 0.0))
        f.error("E-INVALID-VALUE", f.valueAt(at),
                "'" + JsonFields::describe(at) + "' must be a finite number >= 0");
      else
        out = *v;
    };
    bound("abs", t.abs);
    bound("rel", t.rel);
    t.reason = nonEmpty(f, ptr + "/reason").value_or("");
    return t;
  }

  // --- models ---------------------------------------------------------------------------

  void readModel(const std::string& name, const SourceLocation& listedAt) {
    auto doc = loadJson("models/" + name + ".json", listedAt);
    if (!doc) return;
    JsonFields f(*doc, sink_);
    if (!f.object("", {"name", "description", "skeleton", "requires", "lights", "environments", "roles", "inputs"},
                  {"features", "parts", "quality", "incompatible"}, "shading model '" + name + "'"))
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
    m.lights = namesFrom(f, "/lights", allLightTypes(), "light type");
    m.environments = namesFrom(f, "/environments", allEnvironmentModes(), "environment mode");
    if (f.find("/features")) m.features = readFeatures(f);
    m.roles = readRoles(f, m);
    m.inputs = readModelInputs(f, m);
    if (f.find("/quality")) m.quality = readQuality(f, m);
    if (f.find("/incompatible")) m.incompatible = readIncompatible(f, m);
    data_.models.push_back(std::move(m));
  }

  // One "role": "brick" member of a model table (quality levels, incompatible pairs): the
  // role must be the model's and the brick of that role's slot. `what` starts the message.
  std::optional<std::string> roleBinding(JsonFields& f, const std::string& ptr, const std::string& roleName,
                                         const ShadingModel& m, const std::string& what) {
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
      f.error("E-UNKNOWN-BRICK", f.valueAt(ptr),
              what + " binds '" + *id + "' to role '" + role->role + "', but it is not a brick of slot '" + role->slot + "'",
              didYouMean(*id, loadedBricksOf(role->slot)));
      return std::nullopt;
    }
    return id;
  }

  // "quality": {"low": {role: brick}, "medium": {...}}. "high" is the default bindings and is
  // not written (docs/scenes.md "Quality"); the level names are permute/axes.hpp's
  // allQualityLevels() minus "high" (the library does not depend on permute).
  std::map<std::string, std::map<std::string, std::string>> readQuality(JsonFields& f, const ShadingModel& m) {
    static const std::vector<std::string> levels{"low", "medium"};
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
  std::vector<BrickRule> readIncompatible(JsonFields& f, const ShadingModel& m) {
    std::vector<BrickRule> out;
    if (!f.isArray("/incompatible")) return out;
    for (size_t i = 0; i < f.find("/incompatible")->size(); ++i) {
      std::string ptr = JsonFields::element("/incompatible", i);
      if (!f.object(ptr, {"bricks", "reason"}, {}, "incompatible-bricks rule")) continue;
      BrickRule rule;
      rule.reason = f.string(ptr + "/reason").value_or("");
      bool complete = f.isObject(ptr + "/bricks");
      if (complete && f.find(ptr + "/bricks")->empty()) {
        f.error("E-FIELD-TYPE", f.valueAt(ptr + "/bricks"), "an incompatible-bricks rule names no bricks: expected role: brick pairs");
        complete = false;
      }
      if (complete)
        for (const auto& item : f.find(ptr + "/bricks")->items()) {
          auto id = roleBinding(f, JsonFields::member(ptr + "/bricks", item.key()), item.key(), m, "incompatible-bricks rule");
          if (id)
            rule.bricks.emplace_back(item.key(), *id);
          else
            complete = false;
        }
      if (complete && !rule.reason.empty()) out.push_back(std::move(rule));
    }
    return out;
  }

  // A string array whose entries must come from `allowed`, each once.
  std::vector<std::string> namesFrom(JsonFields& f, const std::string& ptr,
                                     const std::vector<std::string>& allowed, const std::string& what) {
    std::vector<std::string> out;
    auto names = f.strings(ptr);
    if (!names) return out;
    for (size_t i = 0; i < names->size(); ++i) {
      const std::string& n = (*names)[i];
      std::string at = JsonFields::element(ptr, i);
      if (std::find(allowed.begin(), allowed.end(), n) == allowed.end())
        f.error("E-UNKNOWN-NAME", f.valueAt(at),
                "unknown " + what + " '" + n + "': expected one of " + quotedList(allowed),
                didYouMean(n, allowed));
      else if (std::find(out.begin(), out.end(), n) != out.end())
        f.error("E-DUPLICATE-NAME", f.valueAt(at), what + " '" + n + "' is listed twice");
      else
        out.push_back(n);
    }
    return out;
  }

  std::vector<ModelFeature> readFeatures(JsonFields& f) {
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

  std::vector<std::string> featureNames(const ShadingModel& m) const {
    std::vector<std::string> names;
    for (const auto& x : m.features) names.push_back(x.name);
    return names;
  }

  // A "feature" member must name a feature of the model.
  std::string featureRef(JsonFields& f, const std::string& ptr, const ShadingModel& m) {
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

  std::vector<ModelRole> readRoles(JsonFields& f, const ShadingModel& m) {
    std::vector<ModelRole> out;
    if (!f.isArray("/roles")) return out;
    std::vector<std::string> known;
    for (const auto& s : data_.slots) known.push_back(s.name);
    for (size_t i = 0; i < f.find("/roles")->size(); ++i) {
      std::string ptr = JsonFields::element("/roles", i);
      if (!f.object(ptr, {"role", "slot", "description"}, {"default", "feature", "lights", "environments"},
                    "model role"))
        continue;
      ModelRole r;
      auto role = identifier(f, ptr + "/role", "role name");
      auto slot = f.string(ptr + "/slot");
      r.description = f.string(ptr + "/description").value_or("");
      r.feature = featureRef(f, ptr + "/feature", m);
      if (f.find(ptr + "/lights")) r.lights = namesFrom(f, ptr + "/lights", m.lights, "light type");
      if (f.find(ptr + "/environments"))
        r.environments = namesFrom(f, ptr + "/environments", m.environments, "environment mode");
      if (slot && std::find(known.begin(), known.end(), *slot) == known.end()) {
        f.error("E-UNKNOWN-SLOT", f.valueAt(ptr + "/slot"),
                "unknown slot '" + *slot + "': the manifest's slots are " + quotedList(known),
                didYouMean(*slot, known));
        slot.reset();
      }
      if (slot && f.find(ptr + "/default")) {
        auto id = f.string(ptr + "/default");
        const Brick* b = id ? findLoadedBrick(*id) : nullptr;
        if (id && (!b || b->slot != *slot)) {
          f.error("E-UNKNOWN-BRICK", f.valueAt(ptr + "/default"),
                  "default '" + *id + "' is not a brick of slot '" + *slot + "'",
                  didYouMean(*id, loadedBricksOf(*slot)));
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

  const Brick* findLoadedBrick(const std::string& id) const {
    for (const auto& b : data_.bricks)
      if (b.id == id) return &b;
    return nullptr;
  }

  std::vector<std::string> loadedBricksOf(const std::string& slot) const {
    std::vector<std::string> ids;
    for (const auto& b : data_.bricks)
      if (b.slot == slot) ids.push_back(b.id);
    return ids;
  }

  std::vector<ModelInput> readModelInputs(JsonFields& f, const ShadingModel& m) {
    std::vector<ModelInput> inputs;
    if (!f.isArray("/inputs")) return inputs;
    std::set<std::string> seen;
    for (size_t i = 0; i < f.find("/inputs")->size(); ++i) {
      std::string ptr = JsonFields::element("/inputs", i);
      if (!f.object(ptr, {"name", "type", "default", "range", "description"}, {"feature", "neutral"},
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
      if (!name || !type || !r || !value) continue;
      in.name = *name;
      in.type = *type;
      in.range = *r;
      in.defaultValue = *value;
      inputs.push_back(std::move(in));
    }
    return inputs;
  }

  fs::path root_;
  DiagnosticSink& sink_;
  LibraryData data_;
  std::map<std::string, SourceLocation> brickIdLocations_;
};

// Guards the source cache: emit may run on several threads over one library.
std::mutex& sourceCacheMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

// Files in the order they were read, positions in file order within each: the checks of
// one brick do not run in the order its fields are written.
static std::vector<Diagnostic> inReadingOrder(std::vector<Diagnostic> diags) {
  std::vector<std::string> files;
  for (const auto& d : diags)
    if (std::find(files.begin(), files.end(), d.where.file) == files.end())
      files.push_back(d.where.file);
  auto rank = [&](const Diagnostic& d) {
    auto index = std::find(files.begin(), files.end(), d.where.file) - files.begin();
    return std::make_tuple(index, d.where.line, d.where.column);
  };
  std::stable_sort(diags.begin(), diags.end(),
                   [&](const Diagnostic& a, const Diagnostic& b) { return rank(a) < rank(b); });
  return diags;
}

ShaderLibrary ShaderLibrary::load(const fs::path& root) {
  DiagnosticSink sink;
  LibraryData data = LibraryLoader(root, sink).run();
  if (sink.hasErrors()) throw DiagnosticError(inReadingOrder(sink.all()));
  ShaderLibrary lib;
  lib.root_ = root;
  lib.units_ = std::move(data.units);
  lib.slots_ = std::move(data.slots);
  lib.bricks_ = std::move(data.bricks);
  lib.models_ = std::move(data.models);
  // Every GLSL file was read during validation; keep it so source() rarely touches disk.
  lib.sources_ = std::move(data.sources);
  return lib;
}

fs::path ShaderLibrary::defaultRoot() {
  const char* env = std::getenv("MATBRICKS_SHADERLIB");
  if (env && *env) return fs::path(env);
  return dataRoot() / "shaderlib";
}

template <class T, class Key>
static const T* findBy(const std::vector<T>& items, const std::string& key, Key T::*member) {
  auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.*member == key; });
  return it == items.end() ? nullptr : &*it;
}

const Slot* ShaderLibrary::findSlot(const std::string& name) const {
  return findBy(slots_, name, &Slot::name);
}

const Brick* ShaderLibrary::findBrick(const std::string& id) const {
  return findBy(bricks_, id, &Brick::id);
}

const ShadingModel* ShaderLibrary::findModel(const std::string& name) const {
  return findBy(models_, name, &ShadingModel::name);
}

const ModelRole* ShadingModel::findRole(const std::string& role) const {
  return findBy(roles, role, &ModelRole::role);
}

const ModelFeature* ShadingModel::findFeature(const std::string& feature) const {
  return findBy(features, feature, &ModelFeature::name);
}

std::vector<std::string> ShadingModel::coreRoles() const {
  std::vector<std::string> out;
  for (const auto& r : roles)
    if (r.feature.empty() && r.lights.empty() && r.environments.empty()) out.push_back(r.role);
  return out;
}

const std::vector<std::string>& allLightTypes() {
  static const std::vector<std::string> types{"dir", "point", "spot", "sphere", "tube"};
  return types;
}

const std::vector<std::string>& allEnvironmentModes() {
  static const std::vector<std::string> modes{"none", "sh", "ibl_lut", "ibl_analytic"};
  return modes;
}

const Unit* ShaderLibrary::findUnit(const std::string& id) const {
  return findBy(units_, id, &Unit::id);
}

std::vector<std::string> ShaderLibrary::brickIds() const {
  std::vector<std::string> ids;
  for (const auto& b : bricks_) ids.push_back(b.id);
  return ids;
}

std::vector<std::string> ShaderLibrary::bricksOfSlot(const std::string& slot) const {
  std::vector<std::string> ids;
  for (const auto& b : bricks_)
    if (b.slot == slot) ids.push_back(b.id);
  return ids;
}

const std::string& ShaderLibrary::source(const std::string& relativeFile) const {
  std::lock_guard<std::mutex> lock(sourceCacheMutex());
  auto it = sources_.find(relativeFile);
  if (it != sources_.end()) return it->second;
  auto text = readFile(root_ / relativeFile);
  if (!text) {
    throw DiagnosticError({{Severity::Error, "E-FILE-NOT-FOUND", {displayPath(relativeFile), 0, 0},
                            "cannot read shader library file '" +
                                (root_ / relativeFile).string() + "'",
                            ""}});
  }
  // std::map never moves its nodes, so the returned reference stays valid.
  return sources_.emplace(relativeFile, std::move(*text)).first->second;
}

std::string ShaderLibrary::displayPath(const std::string& relativeFile) {
  return "shaderlib/" + relativeFile;
}

}  // namespace mb
