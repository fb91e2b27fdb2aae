// Uses of a scene material (docs/scenes.md "Uses"): {"input": value, ...} per use.
#include "load/scene_uses.hpp"

#include <algorithm>

#include "library/value_json.hpp"
#include "load/material_resolve.hpp"

namespace mb {

namespace {

using nlohmann::json;

// What a use may state: every input of the material's model (inputs of features the material
// lacks too: the feature-complete form sets them, permute/specialize.hpp) and the material's
// user parameters.
struct Settable {
  std::string name;
  ValueType type = ValueType::Float;
  Range range;
  std::string rangeOrigin;
  const MaterialParam* own = nullptr;  // the material's parameter, if it has one
};

std::vector<Settable> settableOf(const MaterialDesc& material, const ShaderLibrary& lib) {
  std::vector<Settable> out;
  if (const ShadingModel* model = lib.findModel(material.model))
    for (const auto& in : model->inputs) {
      const MaterialParam* own = material.param(in.name);
      bool runtime = own && !own->constant;
      out.push_back({in.name, in.type, runtime ? own->range : in.range,
                     runtime ? "the range of input '" + in.name + "' of material '" + material.name + "'"
                             : "the range of model input '" + in.name + "'",
                     own});
    }
  for (const auto& p : material.params)
    if (p.user) out.push_back({p.name, p.type, p.range, "the range of parameter '" + p.name + "'", &p});
  return out;
}

MaterialUse readUse(JsonFields& f, const std::string& ptr, const MaterialDesc& material,
                    const std::vector<Settable>& settable) {
  MaterialUse use;
  use.where = f.valueAt(ptr);
  if (!f.isObject(ptr)) return use;
  std::vector<std::string> names;
  for (const auto& s : settable) names.push_back(s.name);
  for (const auto& item : f.find(ptr)->items()) {
    std::string vptr = JsonFields::member(ptr, item.key());
    auto s = std::find_if(settable.begin(), settable.end(), [&](const Settable& x) { return x.name == item.key(); });
    if (s == settable.end()) {
      f.error("E-SCENE-UNKNOWN-INPUT", f.keyAt(vptr),
              "material '" + material.name + "' (model '" + material.model + "') has no input '" + clipped(item.key()) +
                  "'",
              suggest(item.key(), names));
      continue;
    }
    const json& j = item.value();
    size_t n = static_cast<size_t>(componentCount(s->type));
    bool shapeOk = n == 1 ? j.is_number()
                          : j.is_array() && j.size() == n &&
                                std::all_of(j.begin(), j.end(), [](const json& c) { return c.is_number(); });
    if (!shapeOk) {
      f.error("E-SCENE-VALUE-TYPE", f.valueAt(vptr),
              "input '" + s->name + "' is a " + toString(s->type) + ": expected " + jsonShapeOf(s->type) + ", found " +
                  JsonFields::kindOf(j) + (j.is_array() ? " of " + std::to_string(j.size()) : ""));
      continue;
    }
    std::vector<double> value = n == 1 ? std::vector<double>{j.get<double>()} : j.get<std::vector<double>>();
    bool inRange =
        std::all_of(value.begin(), value.end(), [&](double x) { return x >= s->range.lo && x <= s->range.hi; });
    if (!inRange) {
      f.error("E-SCENE-VALUE-RANGE", f.valueAt(vptr),
              "input '" + s->name + "' = " + formatUseValue(value) + " is outside " + s->rangeOrigin + ", " +
                  formatRange(s->range));
      continue;
    }
    // The shader bakes a constant in: a use cannot give it another value.
    if (s->own && s->own->constant && s->own->value != value) {
      f.error("E-SCENE-CONSTANT", f.valueAt(vptr),
              "material '" + material.name + "' fixes '" + s->name + "' as the constant " +
                  formatUseValue(s->own->value) + ": a use cannot set it to " + formatUseValue(value),
              "make '" + s->name + "' a run-time input of the material (\"constant\": false), or drop it from the use");
      continue;
    }
    use.values[s->name] = value;
  }
  return use;
}

}  // namespace

std::string formatUseValue(const std::vector<double>& v) {
  if (v.size() == 1) return formatNumber(v[0]);
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatNumber(v[i]);
  return s + "]";
}

std::vector<MaterialUse> readUses(JsonFields& f, const std::string& ptr, const MaterialDesc& material,
                                  const ShaderLibrary& lib) {
  if (!f.find(ptr)) {
    MaterialUse implicit;
    implicit.where = f.valueAt(ptr);
    return {implicit};
  }
  if (!f.isArray(ptr)) return {MaterialUse{}};
  if (f.find(ptr)->empty()) {
    f.error("E-SCENE-NO-USES", f.valueAt(ptr), "\"uses\" is empty: list at least one use, or leave it out");
    return {MaterialUse{}};
  }
  std::vector<Settable> settable = settableOf(material, lib);
  std::vector<MaterialUse> uses;
  for (size_t i = 0; i < f.find(ptr)->size(); ++i)
    uses.push_back(readUse(f, JsonFields::element(ptr, i), material, settable));
  return uses;
}

}  // namespace mb
