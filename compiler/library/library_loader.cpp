// Reading the shader library from disk: file access, the manifest (schema, units, the
// slot and model lists), each slot's slot.json with its bricks (GLSL files, citations,
// domains, geometry ranges, tolerances), and the field readers the models share. The
// shading models themselves are read in library_models.cpp; LibraryLoader is declared in
// library_loader.hpp.
#include "library/library_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "library/value_json.hpp"

namespace mb {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<std::string> readFile(const fs::path& path, InputFileError* error) {
  InputFileError why;
  auto text = readInputFile(path, input_kind::kLibraryFile, why);
  if (!text && error) *error = why;
  return text;
}

namespace {

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

}  // namespace

LibraryData LibraryLoader::run() {
  auto manifest = loadJson("manifest.json", {});
  if (!manifest) return std::move(data_);
  JsonFields f(*manifest, sink_);
  if (!f.object("", {"schema", "units", "slots", "models"}, {"gltf_defaults"}, "the library manifest"))
    return std::move(data_);
  checkSchema(f);
  readUnits(f);
  forEachName(f, "/slots", "slot", [&](const std::string& n, const SourceLocation& at) { readSlot(n, at); });
  checkBrickReferences();
  forEachName(f, "/models", "model", [&](const std::string& n, const SourceLocation& at) { readModel(n, at); });
  readGltfDefaults(f);
  checkRoughnessKinds();
  return std::move(data_);
}

// --- files -------------------------------------------------------------------------

std::string LibraryLoader::diskPath(const std::string& relative) const {
  return (root_ / relative).lexically_normal().string();
}

// Parses root/<relative>. A missing file is reported at `referencedFrom` (the manifest
// entry that names it) when there is one.
std::optional<JsonDocument> LibraryLoader::loadJson(const std::string& relative, const SourceLocation& referencedFrom) {
  std::string path = diskPath(relative);
  InputFileError error;
  auto text = readFile(path, &error);
  if (!text) {
    SourceLocation at = referencedFrom.file.empty() ? SourceLocation{path, 0, 0} : referencedFrom;
    sink_.error(error.code, at, "cannot read library file '" + path + "': " + error.message);
    return std::nullopt;
  }
  try {
    return JsonDocument::parse(std::move(*text), path);
  } catch (const DiagnosticError& e) {
    for (const auto& d : e.diagnostics()) sink_.error(d.code, d.where, d.message, d.suggestion);
    return std::nullopt;
  }
}

// Resolves a GLSL path given relative to `baseDir` (a folder under the root) to a path
// relative to the root, reads it once, and reports it at `ptr` when it is missing.
std::optional<std::string> LibraryLoader::readGlsl(JsonFields& f, const std::string& ptr, const std::string& baseDir) {
  auto file = f.string(ptr);
  if (!file) return std::nullopt;
  fs::path p = fs::path(*file);
  std::string rel = (fs::path(baseDir) / p).lexically_normal().generic_string();
  if (p.is_absolute() || rel.rfind("..", 0) == 0) {
    f.error("E-INVALID-PATH", f.valueAt(ptr), "'" + *file + "' must be a relative path inside the shader library");
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

void LibraryLoader::checkSchema(JsonFields& f) {
  auto schema = f.number("/schema");
  if (schema && *schema != 1)
    f.error("E-SCHEMA-VERSION", f.valueAt("/schema"),
            "unsupported library schema " + formatNumber(*schema) + ": expected 1");
}

void LibraryLoader::readUnits(JsonFields& f) {
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
void LibraryLoader::forEachName(JsonFields& f, const std::string& ptr, const std::string& what, Fn fn) {
  auto names = f.strings(ptr);
  if (!names) return;
  std::set<std::string> seen;
  for (size_t i = 0; i < names->size(); ++i) {
    std::string at = JsonFields::element(ptr, i);
    const std::string& name = (*names)[i];
    if (!isIdentifier(name)) {
      f.error("E-INVALID-NAME", f.valueAt(at), what + " name '" + name + "' must match [A-Za-z_][A-Za-z0-9_]*");
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

std::optional<std::string> LibraryLoader::identifier(JsonFields& f, const std::string& ptr, const std::string& what) {
  auto s = f.string(ptr);
  if (s && !isIdentifier(*s)) {
    f.error("E-INVALID-NAME", f.valueAt(ptr), what + " '" + *s + "' must match [A-Za-z_][A-Za-z0-9_]*");
    return std::nullopt;
  }
  return s;
}

// A string that must say something (citations, tolerance reasons): the manifest is the
// only place a reader learns why a formula or a tolerance is what it is.
std::optional<std::string> LibraryLoader::nonEmpty(JsonFields& f, const std::string& ptr) {
  auto s = f.string(ptr);
  if (s && s->find_first_not_of(" \t\r\n") == std::string::npos) {
    f.error("E-EMPTY-FIELD", f.valueAt(ptr), "'" + JsonFields::describe(ptr) + "' must not be empty");
    return std::nullopt;
  }
  return s;
}

std::optional<ValueType> LibraryLoader::valueType(JsonFields& f, const std::string& ptr, bool allowGeometry) {
  auto s = f.string(ptr);
  if (!s) return std::nullopt;
  std::vector<std::string> allowed = {"float", "vec2", "vec3"};
  if (allowGeometry) allowed.push_back("Geometry");
  auto t = parseValueType(*s);
  if (!t || (*t == ValueType::Geometry && !allowGeometry)) {
    f.error("E-UNKNOWN-TYPE", f.valueAt(ptr),
            "unknown type '" + *s + "' for '" + JsonFields::describe(ptr) + "': expected one of " + quotedList(allowed),
            didYouMean(*s, allowed));
    return std::nullopt;
  }
  return t;
}

std::optional<Range> LibraryLoader::range(JsonFields& f, const std::string& ptr) {
  auto r = f.range(ptr);
  if (!r) return std::nullopt;
  return Range{r->first, r->second};
}

// Each entry of the unit-id array at `ptr` must name a unit of the manifest.
std::vector<std::string> LibraryLoader::requiredUnits(JsonFields& f, const std::string& ptr) {
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

void LibraryLoader::readSlot(const std::string& folder, const SourceLocation& listedAt) {
  auto doc = loadJson(folder + "/slot.json", listedAt);
  if (!doc) return;
  JsonFields f(*doc, sink_);
  if (!f.object("", {"name", "description", "returns", "params", "bricks"}, {"energy"}, "slot '" + folder + "'"))
    return;
  Slot slot;
  slot.name = folder;
  auto name = f.string("/name");
  if (name && *name != folder)
    f.error("E-NAME-MISMATCH", f.valueAt("/name"),
            "slot name '" + *name + "' differs from its folder '" + folder + "': the folder name is the slot's id");
  slot.description = f.string("/description").value_or("");
  slot.returns = valueType(f, "/returns", false).value_or(ValueType::Float);
  slot.params = readSlotParams(f);
  if (f.find("/energy")) slot.energyRole = oneOf(f, "/energy", brickEnergyRoles()).value_or("");
  data_.slots.push_back(slot);
  if (!f.isArray("/bricks")) return;
  for (size_t i = 0; i < f.find("/bricks")->size(); ++i) readBrick(f, JsonFields::element("/bricks", i), slot);
}

std::vector<SlotParam> LibraryLoader::readSlotParams(JsonFields& f) {
  std::vector<SlotParam> params;
  if (!f.isArray("/params")) return params;
  std::set<std::string> seen;
  for (size_t i = 0; i < f.find("/params")->size(); ++i) {
    std::string ptr = JsonFields::element("/params", i);
    if (!f.object(ptr, {"name", "type"}, {"roughness"}, "slot parameter")) continue;
    auto name = identifier(f, ptr + "/name", "parameter name");
    auto type = valueType(f, ptr + "/type", true);
    if (name && !seen.insert(*name).second)
      f.error("E-DUPLICATE-NAME", f.valueAt(ptr + "/name"), "parameter '" + *name + "' is listed twice");
    if (!name) continue;
    RoughnessKind roughness = readRoughnessKind(f, ptr, *name, type);
    if (type) params.push_back({*name, *type, roughness});
  }
  return params;
}

void LibraryLoader::readBrick(JsonFields& f, const std::string& ptr, const Slot& slot) {
  const json* idValue = f.find(ptr + "/id");
  std::string what = idValue && idValue->is_string() ? "brick '" + idValue->get<std::string>() + "'" : "brick";
  if (!f.object(ptr, {"id", "name", "function", "file", "citation", "requires", "domain", "tolerance"},
                {"geometry", "notes", "truth_note", "unstable_variant", "fp16_twin", "energy", "kernel_roles"}, what))
    return;
  Brick b;
  b.slot = slot.name;
  b.id = brickId(f, ptr + "/id").value_or("");
  b.name = nonEmpty(f, ptr + "/name").value_or("");
  b.function = identifier(f, ptr + "/function", "function name").value_or("");
  b.citation = nonEmpty(f, ptr + "/citation").value_or("");
  b.notes = f.string(ptr + "/notes").value_or("");
  if (f.find(ptr + "/truth_note")) b.truthNote = nonEmpty(f, ptr + "/truth_note").value_or("");
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
  readFp16Twin(f, ptr + "/fp16_twin", b);
  readBrickEnergy(f, ptr, slot, b);
  readKernelRoles(f, ptr + "/kernel_roles", slot, b);
  data_.bricks.push_back(std::move(b));
}

// The naive form a stability fix replaced, kept so validation can show the problem the
// fix solves: {"file": GLSL defining the same function, "problem": what goes wrong}.
void LibraryLoader::readUnstableVariant(JsonFields& f, const std::string& ptr, const Slot& slot, Brick& b) {
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
std::optional<std::string> LibraryLoader::brickId(JsonFields& f, const std::string& ptr) {
  auto id = identifier(f, ptr, "brick id");
  if (!id) return std::nullopt;
  SourceLocation here = f.valueAt(ptr);
  auto [it, inserted] = brickIdLocations_.emplace(*id, here);
  if (!inserted) {
    const SourceLocation& first = it->second;
    f.error("E-DUPLICATE-BRICK", here,
            "duplicate brick id '" + *id + "': already defined at " + first.file + ":" + std::to_string(first.line) +
                ":" + std::to_string(first.column));
  }
  return id;
}

// The domain is the region validation samples; every scalar/vector parameter needs one,
// and nothing else may have one (a typo there would silently leave a parameter unsampled).
std::map<std::string, Range> LibraryLoader::readDomain(JsonFields& f, const std::string& ptr, const Slot& slot) {
  std::map<std::string, Range> domain;
  if (!f.isObject(ptr)) return domain;
  std::vector<std::string> sampled;
  for (const auto& p : slot.params)
    if (p.type != ValueType::Geometry) sampled.push_back(p.name);
  for (const auto& [key, value] : f.find(ptr)->items()) {
    std::string at = JsonFields::member(ptr, key);
    if (std::find(sampled.begin(), sampled.end(), key) == sampled.end()) {
      f.error("E-UNKNOWN-PARAM", f.keyAt(at),
              "domain names '" + key + "', which is not a float/vec2/vec3 parameter of slot '" + slot.name +
                  "' (those are " + quotedList(sampled) + ")",
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

GeometryDomain LibraryLoader::readGeometry(JsonFields& f, const std::string& ptr, const Slot& slot) {
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

Tolerance LibraryLoader::readTolerance(JsonFields& f, const std::string& ptr) {
  Tolerance t;
  if (!f.object(ptr, {"abs", "rel", "reason"}, {}, "tolerance")) return t;
  auto bound = [&](const std::string& key, double& out) {
    std::string at = JsonFields::member(ptr, key);
    auto v = f.number(at);
    if (!v) return;
    if (!(std::isfinite(*v) && *v >= 0.0))
      f.error("E-INVALID-VALUE", f.valueAt(at), "'" + JsonFields::describe(at) + "' must be a finite number >= 0");
    else
      out = *v;
  };
  bound("abs", t.abs);
  bound("rel", t.rel);
  t.reason = nonEmpty(f, ptr + "/reason").value_or("");
  return t;
}

}  // namespace mb
