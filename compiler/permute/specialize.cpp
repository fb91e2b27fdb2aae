// Quality selection and feature folding (docs/scenes.md "Quality", "Folding"). Both return an
// ordinary MaterialDesc, so emit, compile and validate handle a specialized material as any
// other: the reference follows MaterialDesc::bricks and ::params automatically.
#include "permute/specialize.hpp"

#include <algorithm>
#include <cctype>

#include "core/json_fields.hpp"
#include "load/scene_uses.hpp"

namespace mb {

namespace {

bool contains(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

std::string at(const SourceLocation& l) { return l.file.empty() ? "" : " (" + formatLocation(l) + ")"; }

bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Does the surface code mention `.<input>` as a whole member name? A plain token scan, not a
// GLSL parse: it also counts reads (`x = m.clearCoat`), which is deliberately conservative,
// since a folded input is also gone from MaterialInputs and the read would not compile.
bool surfaceMentions(const SurfaceCode& s, const std::string& input) {
  const std::string token = "." + input;
  for (size_t pos = s.glsl.find(token); pos != std::string::npos; pos = s.glsl.find(token, pos + 1)) {
    size_t end = pos + token.size();
    if (end >= s.glsl.size() || !isIdentChar(s.glsl[end])) return true;
  }
  return false;
}

// The inputs that belong to `feature`, and the one with a neutral value.
const ModelInput* neutralInputOf(const ShadingModel& model, const std::string& feature) {
  for (const auto& in : model.inputs)
    if (in.feature == feature && !in.neutral.empty()) return &in;
  return nullptr;
}

}  // namespace

const ShadingModel& modelOf(const MaterialDesc& m, const ShaderLibrary& lib) {
  const ShadingModel* model = lib.findModel(m.model);
  if (!model)
    throw DiagnosticError({{Severity::Error,
                            "E-UNKNOWN-MODEL",
                            {m.sourceFile, 0, 0},
                            "material '" + m.name + "' names unknown model '" + m.model + "'"}});
  return *model;
}

MaterialDesc applyQuality(const MaterialDesc& material, Quality quality, const ShaderLibrary& lib) {
  if (quality == Quality::High) return material;
  const ShadingModel& model = modelOf(material, lib);
  auto level = model.quality.find(qualityName(quality));
  if (level == model.quality.end())
    throw DiagnosticError({{Severity::Error,
                            "E-PERMUTATION-INVALID",
                            {material.sourceFile, 0, 0},
                            "model '" + model.name + "' defines no quality level '" + qualityName(quality) + "'"}});
  MaterialDesc out = material;
  for (const auto& [role, brick] : level->second) {
    auto bound = out.bricks.find(role);
    // A role the material does not have (its feature is off), or one it chose itself
    // (brickLocations records every explicit choice), keeps what it has.
    if (bound == out.bricks.end() || material.brickLocations.count(role)) continue;
    bound->second = brick;
  }
  // Likewise a light method the material did not choose takes the level's (docs/models.md
  // "Light methods").
  for (const auto& c : model.lightMethods) {
    const std::string light = lightTypeName(c.light);
    auto pick = c.quality.find(qualityName(quality));
    if (pick != c.quality.end() && !material.lightMethodLocations.count(light)) out.lightMethods[light] = pick->second;
  }
  return out;
}

std::optional<std::string> foldBlocker(const MaterialDesc& material, const std::string& feature,
                                       const std::vector<MaterialUse>& uses, const ShaderLibrary& lib) {
  const ShadingModel& model = modelOf(material, lib);
  if (!material.has(feature)) return "the material does not enable it";
  const ModelInput* in = neutralInputOf(model, feature);
  if (!in) return "model '" + model.name + "' gives it no neutral input";
  if (material.surface.present() && surfaceMentions(material.surface, in->name))
    return "the surface code uses m." + in->name + at(material.surface.where);
  const MaterialParam* p = material.param(in->name);
  std::vector<MaterialUse> implicit(1);
  for (const auto& use : uses.empty() ? implicit : uses) {
    std::vector<double> value;
    auto stated = use.values.find(in->name);
    if (stated != use.values.end()) {
      value = stated->second;
    } else if (p && !p->constant) {
      return "a use leaves run-time input '" + in->name + "' unstated" + at(use.where);
    } else {
      value = p ? p->value : in->defaultValue;
    }
    if (value != in->neutral)
      return "a use sets " + in->name + " = " + formatUseValue(value) + " (neutral " + formatUseValue(in->neutral) +
             ")" + at(use.where);
  }
  return std::nullopt;
}

MaterialDesc foldFeatures(const MaterialDesc& material, const std::vector<std::string>& folded,
                          const ShaderLibrary& lib) {
  const ShadingModel& model = modelOf(material, lib);
  MaterialDesc out = material;
  auto isFolded = [&](const std::string& f) { return !f.empty() && contains(folded, f); };
  out.features.erase(std::remove_if(out.features.begin(), out.features.end(), isFolded), out.features.end());
  for (const auto& r : model.roles)
    if (isFolded(r.feature)) {
      out.bricks.erase(r.role);
      out.brickLocations.erase(r.role);
    }
  auto inputOfFolded = [&](const MaterialParam& p) {
    if (p.user) return false;
    for (const auto& in : model.inputs)
      if (in.name == p.name) return isFolded(in.feature);
    return false;
  };
  out.params.erase(std::remove_if(out.params.begin(), out.params.end(), inputOfFolded), out.params.end());
  return out;
}

MaterialDesc featureComplete(const MaterialDesc& material, const MaterialUse& use, const ShaderLibrary& lib) {
  const ShadingModel& model = modelOf(material, lib);
  MaterialDesc out = material;
  out.features.clear();
  for (const auto& f : model.features) out.features.push_back(f.name);
  // Only inputs of features the material lacks are set. Pass the specialized material (the
  // plan's Permutation::material, folded already): a folded feature is then "lacking" and is
  // switched on at the use's (neutral) value, while a feature the plan kept keeps its run-time
  // input, exactly as the pruned permutation has it; deciding per use instead would pin an
  // input the pruned form still reads when another use keeps the feature.
  auto setFromUse = [&](const ModelInput& in) { return !in.feature.empty() && !material.has(in.feature); };
  for (const auto& r : model.roles) {
    if (r.feature.empty() || material.has(r.feature)) continue;
    if (r.defaultBrick.empty())
      throw DiagnosticError({{Severity::Error,
                              "E-MISSING-BRICK",
                              {material.sourceFile, 0, 0},
                              "the feature-complete form of '" + material.name + "' needs role '" + r.role +
                                  "', which has no default brick"}});
    out.bricks[r.role] = r.defaultBrick;
  }
  out.params.clear();
  for (const auto& in : model.inputs) {
    const MaterialParam* own = material.param(in.name);
    if (!setFromUse(in)) {
      if (own && !own->user) out.params.push_back(*own);
      continue;
    }
    MaterialParam p;
    p.name = in.name;
    p.type = in.type;
    p.constant = true;
    p.range = in.range;
    auto stated = use.values.find(in.name);
    p.value = stated != use.values.end() ? stated->second : !in.neutral.empty() ? in.neutral : in.defaultValue;
    p.where = own ? own->where : use.where;
    out.params.push_back(p);
  }
  for (const auto& p : material.params)
    if (p.user) out.params.push_back(p);
  return out;
}

}  // namespace mb
