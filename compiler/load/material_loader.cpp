// Material JSON -> MaterialDesc (format: docs/formats.md, "Material JSON"). The loader checks
// the material against the library and collects every problem, each at the key or value
// that causes it, before failing once.
#include <algorithm>
#include <optional>
#include <tuple>

#include "core/json_fields.hpp"
#include "library/value_json.hpp"
#include "load/material_desc.hpp"

namespace mb {

using nlohmann::json;

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

class MaterialLoader {
 public:
  MaterialLoader(const JsonDocument& doc, const ShaderLibrary& lib, DiagnosticSink& sink)
      : doc_(doc), lib_(lib), f_(doc, sink) {}

  MaterialDesc run() {
    desc_.sourceFile = doc_.file();
    if (!f_.object("", {"name", "model", "bricks"}, {"description", "parameters"}, "material"))
      return desc_;
    readName();
    desc_.description = f_.string("/description").value_or("");
    const ShadingModel* model = readModel();
    readBricks(model);
    readParameters(model);
    return desc_;
  }

 private:
  void readName() {
    auto name = f_.string("/name");
    if (!name) return;
    if (!isIdentifier(*name)) {
      // The name becomes part of GLSL entry points, C++ struct names and file names.
      f_.error("E-INVALID-NAME", f_.valueAt("/name"),
               "material name '" + *name + "' must match [A-Za-z_][A-Za-z0-9_]*");
      return;
    }
    desc_.name = *name;
  }

  const ShadingModel* readModel() {
    auto name = f_.string("/model");
    if (!name) return nullptr;
    const ShadingModel* model = lib_.findModel(*name);
    if (!model) {
      std::vector<std::string> known;
      for (const auto& m : lib_.models()) known.push_back(m.name);
      f_.error("E-UNKNOWN-MODEL", f_.valueAt("/model"),
               "unknown shading model '" + *name + "': the library has " + quotedList(known),
               didYouMean(*name, known));
      return nullptr;
    }
    desc_.model = model->name;
    return model;
  }

  // --- bricks ---------------------------------------------------------------------------

  void readBricks(const ShadingModel* model) {
    if (!f_.isObject("/bricks")) return;
    // Without a known model, the library's slots are the best check of the keys we have.
    std::vector<std::string> slots = model ? model->slots : librarySlots();
    for (const auto& [slot, value] : f_.find("/bricks")->items()) {
      std::string ptr = JsonFields::member("/bricks", slot);
      if (!contains(slots, slot)) {
        reportUnknownSlot(ptr, slot, slots, model);
        continue;
      }
      auto id = f_.string(ptr);
      if (id && checkBrick(ptr, slot, *id)) {
        desc_.bricks[slot] = *id;
        desc_.brickLocations[slot] = f_.valueAt(ptr);
      }
    }
    if (!model) return;
    for (const auto& slot : model->slots) {
      if (f_.find("/bricks")->contains(slot)) continue;
      f_.error("E-MISSING-FIELD", f_.valueAt("/bricks"),
               "bricks is missing slot '" + slot + "' of model '" + model->name +
                   "': choose one of " + quotedList(lib_.bricksOfSlot(slot)));
    }
  }

  std::vector<std::string> librarySlots() const {
    std::vector<std::string> names;
    for (const auto& s : lib_.slots()) names.push_back(s.name);
    return names;
  }

  void reportUnknownSlot(const std::string& ptr, const std::string& slot,
                         const std::vector<std::string>& slots, const ShadingModel* model) {
    std::string message =
        model && lib_.findSlot(slot)
            ? "slot '" + slot + "' is not used by model '" + model->name + "' (its slots are " +
                  quotedList(slots) + ")"
            : "unknown slot '" + slot + "': expected one of " + quotedList(slots);
    f_.error("E-UNKNOWN-SLOT", f_.keyAt(ptr), message, didYouMean(slot, slots));
  }

  // True if `id` names a brick of `slot`; otherwise reports why not.
  bool checkBrick(const std::string& ptr, const std::string& slot, const std::string& id) {
    std::vector<std::string> ofSlot = lib_.bricksOfSlot(slot);
    const Brick* brick = lib_.findBrick(id);
    if (!brick) {
      // Prefer suggestions that fit the slot; fall back to any brick (wrong slot is a
      // separate, clearer error once the user picks it).
      std::string suggestion = didYouMean(id, ofSlot);
      if (suggestion.empty()) suggestion = didYouMean(id, lib_.brickIds());
      f_.error("E-UNKNOWN-BRICK", f_.valueAt(ptr),
               "unknown brick '" + id + "' for slot '" + slot + "': expected one of " +
                   quotedList(ofSlot),
               suggestion);
      return false;
    }
    if (brick->slot != slot) {
      f_.error("E-BRICK-WRONG-SLOT", f_.valueAt(ptr),
               "brick '" + id + "' fills slot '" + brick->slot + "', expected a '" + slot +
                   "' brick: one of " + quotedList(ofSlot));
      return false;
    }
    return true;
  }

  // --- parameters -----------------------------------------------------------------------

  void readParameters(const ShadingModel* model) {
    if (!model) return;  // input names and types come from the model
    std::map<std::string, MaterialParam> given;
    if (f_.find("/parameters") && f_.isObject("/parameters")) {
      std::vector<std::string> inputNames;
      for (const auto& in : model->inputs) inputNames.push_back(in.name);
      for (const auto& [name, value] : f_.find("/parameters")->items()) {
        std::string ptr = JsonFields::member("/parameters", name);
        auto input = std::find_if(model->inputs.begin(), model->inputs.end(),
                                  [&](const ModelInput& in) { return in.name == name; });
        if (input == model->inputs.end()) {
          f_.error("E-UNKNOWN-FIELD", f_.keyAt(ptr),
                   "unknown parameter '" + name + "': model '" + model->name + "' has inputs " +
                       quotedList(inputNames),
                   didYouMean(name, inputNames));
          continue;
        }
        if (auto p = readParameter(ptr, *input)) given[name] = *p;
      }
    }
    // One entry per model input, in the model's order, so the emitted struct is stable.
    for (const auto& in : model->inputs) {
      auto it = given.find(in.name);
      desc_.params.push_back(it != given.end() ? it->second : defaultParameter(in));
    }
  }

  // Inputs a material does not mention are folded in as constants at the model's default.
  MaterialParam defaultParameter(const ModelInput& in) const {
    MaterialParam p;
    p.name = in.name;
    p.type = in.type;
    p.value = in.defaultValue;
    p.constant = true;
    p.range = in.range;
    p.where = f_.valueAt("/model");  // the value comes from the model
    return p;
  }

  std::optional<MaterialParam> readParameter(const std::string& ptr, const ModelInput& in) {
    if (!f_.object(ptr, {"type", "default"}, {"range", "constant"}, "parameter '" + in.name + "'"))
      return std::nullopt;
    bool ok = checkDeclaredType(ptr + "/type", in);
    std::optional<Range> range = readRange(ptr + "/range", in);
    ok = ok && range.has_value();
    // The model's type is authoritative for the value's shape, even if "type" was wrong.
    auto value = readTypedValue(f_, ptr + "/default", in.type);
    if (value) {
      // A broken "range" is already reported; the model's range still catches a bad default.
      bool own = range && f_.find(ptr + "/range");
      std::string origin = own ? "the parameter's range" : "the range of model input '" + in.name + "'";
      ok = checkInRange(f_, ptr + "/default", *value, range.value_or(in.range), origin) && ok;
    }
    auto constant = f_.boolean(ptr + "/constant");
    if (f_.find(ptr + "/constant") && !constant) ok = false;
    if (!ok || !value) return std::nullopt;
    MaterialParam p;
    p.name = in.name;
    p.type = in.type;
    p.value = *value;
    p.constant = constant.value_or(false);
    p.range = *range;
    p.where = f_.keyAt(ptr);
    return p;
  }

  bool checkDeclaredType(const std::string& ptr, const ModelInput& in) {
    auto declared = f_.string(ptr);
    if (!declared) return false;
    const std::vector<std::string> allowed = {"float", "vec2", "vec3"};
    if (!contains(allowed, *declared)) {
      f_.error("E-PARAM-TYPE", f_.valueAt(ptr),
               "unknown parameter type '" + *declared + "': expected one of " + quotedList(allowed),
               didYouMean(*declared, allowed));
      return false;
    }
    if (*declared != toString(in.type)) {
      f_.error("E-PARAM-TYPE", f_.valueAt(ptr),
               "parameter '" + in.name + "' is declared '" + *declared + "' but model input '" +
                   in.name + "' is a " + toString(in.type));
      return false;
    }
    return true;
  }

  // The parameter's own range, which must narrow the model's (the model's range is where its
  // formulas are valid), or the model's range when absent.
  std::optional<Range> readRange(const std::string& ptr, const ModelInput& in) {
    if (!f_.find(ptr)) return in.range;
    auto r = f_.range(ptr);
    if (!r) return std::nullopt;
    Range range{r->first, r->second};
    if (range.lo < in.range.lo || range.hi > in.range.hi) {
      f_.error("E-PARAM-RANGE", f_.valueAt(ptr),
               "'" + JsonFields::describe(ptr) + "' " + formatRange(range) +
                   " must lie inside the range " + formatRange(in.range) + " of model input '" +
                   in.name + "'");
      return std::nullopt;
    }
    return range;
  }

  const JsonDocument& doc_;
  const ShaderLibrary& lib_;
  JsonFields f_;
  MaterialDesc desc_;
};

MaterialDesc loadDocument(const JsonDocument& doc, const ShaderLibrary& lib) {
  DiagnosticSink sink;
  MaterialDesc desc = MaterialLoader(doc, lib, sink).run();
  if (!sink.hasErrors()) return desc;
  // Report in file order: nlohmann iterates object keys alphabetically, not as written.
  std::vector<Diagnostic> diags = sink.all();
  std::stable_sort(diags.begin(), diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.where.line, a.where.column) < std::tie(b.where.line, b.where.column);
  });
  throw DiagnosticError(std::move(diags));
}

}  // namespace

MaterialDesc loadMaterialJson(const std::string& path, const ShaderLibrary& lib) {
  return loadDocument(JsonDocument::load(path), lib);
}

MaterialDesc parseMaterialJson(const std::string& text, const std::string& file,
                               const ShaderLibrary& lib) {
  return loadDocument(JsonDocument::parse(text, file), lib);
}

}  // namespace mb
