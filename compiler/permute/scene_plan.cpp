// The scene planner (docs/scenes.md "Planning"): per material, fold what every use proves
// neutral, then one permutation per environment x precision x quality of the scene, with the
// scene's light types. Nothing is enumerated and stripped: the required set is built directly,
// and the possible count comes from validCombinationCount() (arithmetic, not a list).
#include "permute/scene_plan.hpp"

#include <algorithm>
#include <set>

#include "core/json_fields.hpp"
#include "permute/specialize.hpp"

namespace mb {

namespace {

// The models that could shade this point (for the suggestion of E-PERMUTATION-INVALID).
std::string modelsThatCan(const AxisPoint& p, const ShaderLibrary& lib) {
  std::vector<std::string> names;
  AxisPoint bare = p;
  bare.features.clear();
  for (const auto& m : lib.models())
    if (!invalidReason(m, bare)) names.push_back(m.name);
  return names.empty() ? "remove it from the scene"
                       : "remove it from the scene, or use a model that can: " + quotedList(names);
}

// Says which part of the scene the material's model cannot take: each light, then the
// environment, precision and quality, tested alone so the message names the culprit.
void reportInvalid(const SceneDesc& scene, const SceneMaterial& sm, const ShadingModel& model, const AxisPoint& point,
                   const ShaderLibrary& lib, std::set<std::string>& said, DiagnosticSink& sink) {
  auto report = [&](const AxisPoint& probe, const std::string& what, const SourceLocation& at) {
    auto reason = invalidReason(model, probe);
    if (!reason) return false;
    std::string message = "material '" + sm.material.name + "' cannot be shaded with " + what + " of scene '" +
                          scene.name + "' (" + formatLocation(at) + "): " + *reason;
    if (said.insert(message).second) sink.error("E-PERMUTATION-INVALID", sm.where, message, modelsThatCan(probe, lib));
    return true;
  };
  AxisPoint base = point;
  base.lights.clear();
  base.environment = EnvironmentMode::None;
  base.precision = Precision::Fp32;
  base.quality = Quality::High;
  bool named = report(base, "its features", sm.where);
  for (const auto& l : scene.lights) {
    AxisPoint p = base;
    p.lights = {l.type};
    named |=
        report(p, "light " + (l.name.empty() ? "" : "'" + l.name + "' ") + "(" + lightTypeName(l.type) + ")", l.where);
  }
  AxisPoint p = base;
  p.environment = point.environment;
  named |= report(p, "environment '" + environmentModeName(point.environment) + "'", scene.environmentWhere);
  p = base;
  p.precision = point.precision;
  named |= report(p, "precision '" + precisionName(point.precision) + "'", scene.precisionWhere);
  p = base;
  p.quality = point.quality;
  named |= report(p, "quality '" + qualityName(point.quality) + "'", scene.qualityWhere);
  if (!named)
    report(point, "the scene's combination", scene.file.empty() ? sm.where : SourceLocation(scene.file, 1, 1));
}

// A brick rule of the model the material's bindings break at one of the scene's points: at
// the material's entry in the scene, naming where the material chose the brick.
void reportBrokenRule(const SceneMaterial& sm, const ShadingModel& model, const Permutation& p,
                      const std::string& message, std::set<std::string>& said, DiagnosticSink& sink) {
  SourceLocation chosen = invalidLocation(model, p);
  std::string text = "material '" + sm.material.name + "' cannot be compiled for this scene: " + message +
                     (chosen.line > 0 ? " (brick chosen at " + formatLocation(chosen) + ")" : "");
  if (said.insert(text).second)
    sink.error(
        "E-PERMUTATION-INVALID", sm.where, text,
        "bind another brick to one of these roles in the material, or drop the environment or quality level from the scene");
}

void noteQuality(MaterialPlanNote& note, const MaterialDesc& base, const MaterialDesc& q, Quality level) {
  for (const auto& [role, brick] : q.bricks) {
    auto was = base.bricks.find(role);
    if (was != base.bricks.end() && was->second != brick)
      note.qualityBricks.push_back({qualityName(level) + ":" + role, brick});
  }
  for (const auto& [light, method] : q.lightMethods) {
    auto was = base.lightMethods.find(light);
    if (was != base.lightMethods.end() && was->second != method)
      note.qualityBricks.push_back({qualityName(level) + ":" + light + " lights", method});
  }
}

void sortRequired(ScenePlan& plan) {
  std::sort(plan.required.begin(), plan.required.end(),
            [](const Permutation& a, const Permutation& b) { return a.key() < b.key(); });
  plan.required.erase(std::unique(plan.required.begin(), plan.required.end(),
                                  [](const Permutation& a, const Permutation& b) { return a.key() == b.key(); }),
                      plan.required.end());
}

void addPossible(ScenePlan& plan, const ShadingModel& model, size_t& largest) {
  size_t n = validCombinationCount(model);
  plan.possible += n;
  if (n > largest) {
    largest = n;
    plan.possibleAxes = axisSizes(model);
  }
}

}  // namespace

ScenePlan planScene(const SceneDesc& scene, const ShaderLibrary& lib) {
  ScenePlan plan;
  DiagnosticSink sink;
  const std::vector<LightType> lights = scene.lightTypes();
  size_t largest = 0;
  for (const auto& sm : scene.materials) {
    const ShadingModel& model = modelOf(sm.material, lib);
    addPossible(plan, model, largest);
    std::set<std::string> said;
    bool valid = true;
    for (EnvironmentMode env : scene.environments)
      for (Precision precision : scene.precisions)
        for (Quality quality : scene.qualities) {
          AxisPoint point{sm.material.features, lights, env, precision, quality};
          if (!invalidReason(model, point)) continue;
          reportInvalid(scene, sm, model, point, lib, said, sink);
          valid = false;
        }
    if (!valid) continue;

    MaterialPlanNote note;
    note.material = sm.material.name;
    for (const auto& f : model.features)
      if (!sm.material.has(f.name)) note.absent.push_back(f.name);
    for (const auto& f : sm.material.features) {
      auto blocker = foldBlocker(sm.material, f, sm.uses, lib);
      if (blocker)
        note.keptReasons.push_back({f, *blocker});
      else
        note.folded.push_back(f);
    }
    const MaterialDesc base = foldFeatures(sm.material, note.folded, lib);
    for (Quality quality : scene.qualities) {
      plan.specialized.push_back(applyQuality(base, quality, lib));
      const MaterialDesc& spec = plan.specialized.back();
      noteQuality(note, base, spec, quality);
      for (EnvironmentMode env : scene.environments)
        for (Precision precision : scene.precisions) {
          Permutation p;
          p.material = &spec;
          p.lights = lights;
          p.environment = env;
          p.precision = precision;
          p.quality = quality;
          p.folded = note.folded;
          if (auto broken = brokenBrickRule(model, p)) {
            reportBrokenRule(sm, model, p, broken->message, said, sink);
            continue;
          }
          plan.required.push_back(p);
        }
    }
    plan.notes.push_back(std::move(note));
  }
  sink.throwIfErrors();
  sortRequired(plan);
  for (const auto& [axis, n] : std::vector<std::pair<std::string, size_t>>{{"environment", scene.environments.size()},
                                                                           {"precision", scene.precisions.size()},
                                                                           {"quality", scene.qualities.size()}})
    if (n > 1) plan.requiredAxes.push_back({axis, n});
  return plan;
}

ScenePlan planMaterials(const std::vector<MaterialDesc>& materials, const AxisPoint& axes, const ShaderLibrary& lib) {
  ScenePlan plan;
  size_t largest = 0;
  for (const auto& m : materials) {
    const ShadingModel& model = modelOf(m, lib);
    addPossible(plan, model, largest);
    // An invalid combination is left to the emitter's checkPermutation (the same rule,
    // reported at the material file), except a quality level the model lacks, which
    // applyQuality reports.
    plan.specialized.push_back(applyQuality(m, axes.quality, lib));
    MaterialPlanNote note;
    note.material = m.name;
    noteQuality(note, m, plan.specialized.back(), axes.quality);
    plan.notes.push_back(std::move(note));
    Permutation p;
    p.material = &plan.specialized.back();
    p.lights = axes.lights;
    p.environment = axes.environment;
    p.precision = axes.precision;
    p.quality = axes.quality;
    plan.required.push_back(p);
  }
  // Input order is kept: `compile a.json b.json` prints and writes in the order given.
  return plan;
}

std::string diffKeys(const std::vector<std::string>& required, const std::vector<std::string>& present) {
  std::set<std::string> need(required.begin(), required.end()), have(present.begin(), present.end());
  std::string missing, extra;
  for (const auto& k : need)
    if (!have.count(k)) missing += "- " + k + "\n";
  if (missing.empty()) return "";
  for (const auto& k : have)
    if (!need.count(k)) extra += "+ " + k + "\n";
  return missing + extra;
}

}  // namespace mb
