// INTERIM (replaced by the scene planner).
#include "permute/scene_plan.hpp"

namespace mb {

ScenePlan planScene(const SceneDesc& scene, const ShaderLibrary&) {
  throw DiagnosticError({{Severity::Error, "E-SCENE", {scene.file, 0, 0}, "scenes not implemented yet"}});
}

ScenePlan planMaterials(const std::vector<MaterialDesc>& materials, const AxisPoint& axes, const ShaderLibrary&) {
  ScenePlan plan;
  for (const auto& m : materials) {
    Permutation p;
    p.material = &m;
    p.lights = axes.lights;
    p.environment = axes.environment;
    p.precision = axes.precision;
    p.quality = axes.quality;
    plan.required.push_back(p);
  }
  return plan;
}

std::string explainText(const ScenePlan& plan, size_t compiled, size_t uniqueSpirv) {
  return "required " + std::to_string(plan.required.size()) + ", compiled " + std::to_string(compiled) +
         ", unique " + std::to_string(uniqueSpirv) + "\n";
}

std::string diffKeys(const std::vector<std::string>&, const std::vector<std::string>&) { return ""; }

}  // namespace mb
