// The permutation axes and their validity rules: the only place that says which combinations
// go together (docs/scenes.md "Axes and validity"). The emitter (checkPermutation), the scene
// planner and the --explain counts all ask invalidReason().
#include "permute/axes.hpp"

#include <algorithm>

#include "core/json_fields.hpp"

namespace mb {

namespace {

template <class T>
bool contains(const std::vector<T>& v, const T& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

std::vector<std::string> featureNames(const ShadingModel& model) {
  std::vector<std::string> out;
  for (const auto& f : model.features) out.push_back(f.name);
  return out;
}

// Levels the model defines: "high" (its default bindings) always, others by its manifest.
bool definesQuality(const ShadingModel& model, Quality quality) {
  return quality == Quality::High || model.quality.count(qualityName(quality)) > 0;
}

}  // namespace

std::optional<std::string> invalidReason(const ShadingModel& model, const AxisPoint& point) {
  const std::string m = "model '" + model.name + "'";
  for (const auto& f : point.features)
    if (!model.findFeature(f))
      return m + " has no feature '" + f + "' (it has " + quotedList(featureNames(model)) + ")";
  for (LightType t : point.lights)
    if (!contains(model.lights, t))
      return m + " does not shade '" + lightTypeName(t) + "' lights (it shades " +
             quotedList(lightTypeNames(model.lights)) + ")";
  if (!contains(model.environments, point.environment))
    return m + " has no environment mode '" + environmentModeName(point.environment) + "' (it has " +
           quotedList(environmentModeNames(model.environments)) + ")";
  if (!definesQuality(model, point.quality))
    return m + " defines no quality level '" + qualityName(point.quality) +
           "' (its manifest's \"quality\" table has no such level)";
  return std::nullopt;
}

std::optional<std::string> invalidReason(const ShadingModel& model, const Permutation& perm) {
  AxisPoint p;
  p.features = perm.material->features;
  // Folded features were features of the material: they must be the model's too.
  p.features.insert(p.features.end(), perm.folded.begin(), perm.folded.end());
  p.lights = perm.lights;
  p.environment = perm.environment;
  p.precision = perm.precision;
  p.quality = perm.quality;
  if (auto reason = invalidReason(model, p)) return reason;
  if (auto broken = brokenBrickRule(model, perm)) return broken->message;
  return std::nullopt;
}

bool roleActive(const ModelRole& role, const Permutation& perm) {
  if (!role.feature.empty() && !perm.material->has(role.feature)) return false;
  // A role with a method exists where one of its lights is shaded and shaded by that method.
  if (!role.lights.empty() && std::none_of(role.lights.begin(), role.lights.end(), [&](LightType t) {
        return perm.hasLight(t) && (role.method.empty() || perm.material->lightMethod(t) == role.method);
      }))
    return false;
  if (!role.environments.empty() && !contains(role.environments, perm.environment)) return false;
  return true;
}

std::optional<BrokenBrickRule> brokenBrickRule(const ShadingModel& model, const Permutation& perm) {
  for (const auto& rule : model.incompatible) {
    bool broken = true;
    std::string pairs;
    for (const auto& [roleName, brick] : rule.bricks) {
      const ModelRole* role = model.findRole(roleName);
      auto bound = perm.material->bricks.find(roleName);
      broken =
          broken && role && roleActive(*role, perm) && bound != perm.material->bricks.end() && bound->second == brick;
      pairs += (pairs.empty() ? "" : " with ") + roleName + " = " + brick;
    }
    if (broken)
      return BrokenBrickRule{&rule, "model '" + model.name + "' does not combine " + pairs + " (environment '" +
                                        environmentModeName(perm.environment) + "', quality '" +
                                        qualityName(perm.quality) + "'): " + rule.reason};
  }
  return std::nullopt;
}

SourceLocation invalidLocation(const ShadingModel& model, const Permutation& perm) {
  if (auto broken = brokenBrickRule(model, perm))
    for (const auto& [role, brick] : broken->rule->bricks) {
      auto chosen = perm.material->brickLocations.find(role);
      if (chosen != perm.material->brickLocations.end()) return chosen->second;
    }
  // A light, environment, feature or quality the model lacks: at the model's name.
  if (perm.material->modelWhere.line > 0) return perm.material->modelWhere;
  return SourceLocation(perm.material->sourceFile, 0, 0);
}

std::vector<AxisSize> axisSizes(const ShadingModel& model) {
  return {{"features", size_t{1} << model.features.size()},
          {"lights", size_t{1} << allLightTypes().size()},
          {"environment", allEnvironmentModes().size()},
          {"precision", allPrecisions().size()},
          {"quality", allQualities().size()}};
}

// Every rule of invalidReason() looks at one axis at a time, so the valid points are the
// product of each axis's valid values: a feature or light subset is valid exactly when all
// its members are. Each value is still judged by invalidReason() itself (against a valid
// base point), so this count cannot drift from the rules. tests/test_scene_axes.cpp checks it
// against a brute-force enumeration of the whole product.
size_t validCombinationCount(const ShadingModel& model) {
  AxisPoint base;
  base.lights = {};
  base.environment = model.environments.empty() ? EnvironmentMode::None : model.environments.front();
  auto validWith = [&](auto&& set) {
    AxisPoint p = base;
    set(p);
    return !invalidReason(model, p).has_value();
  };
  size_t features = 0;
  for (const auto& f : model.features) features += validWith([&](AxisPoint& p) { p.features = {f.name}; });
  size_t lights = 0;
  for (LightType t : allLightTypes()) lights += validWith([&](AxisPoint& p) { p.lights = {t}; });
  size_t envs = 0;
  for (EnvironmentMode e : allEnvironmentModes()) envs += validWith([&](AxisPoint& p) { p.environment = e; });
  size_t precisions = 0;
  for (Precision x : allPrecisions()) precisions += validWith([&](AxisPoint& p) { p.precision = x; });
  size_t qualities = 0;
  for (Quality q : allQualities()) qualities += validWith([&](AxisPoint& p) { p.quality = q; });
  if (!validWith([](AxisPoint&) {})) return 0;
  return (size_t{1} << features) * (size_t{1} << lights) * envs * precisions * qualities;
}

}  // namespace mb
