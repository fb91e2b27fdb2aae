// A scene: what a frame really contains (DESIGN.md vocabulary "scene"; docs/scenes.md).
// Read from scene JSON, or from a glTF 2.0 file (KHR_lights_punctual lights, the materials
// its meshes use). The planner (permute/scene_plan.hpp) derives the required permutations
// from it directly.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/environment_mode.hpp"
#include "core/light_type.hpp"
#include "core/optimization_level.hpp"
#include "core/precision.hpp"
#include "core/quality.hpp"
#include "core/target.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"

namespace mb {

struct SceneLight {
  LightType type = LightType::Dir;
  std::string name;  // as written, may be empty
  SourceLocation where;
};

// One use of a material in the scene: the values its inputs take there. An input not named
// keeps the material's own value (its constant, or any value of its range when it is a
// run-time input).
struct MaterialUse {
  std::map<std::string, std::vector<double>> values;  // model or user input -> value
  SourceLocation where;
};

struct SceneMaterial {
  MaterialDesc material;          // loaded and resolved
  std::vector<MaterialUse> uses;  // at least one (an implicit use at the material's values)
  SourceLocation where;           // where the scene names it
};

struct SceneDesc {
  std::string name;
  std::string file;
  std::vector<SceneLight> lights;
  std::vector<EnvironmentMode> environments{EnvironmentMode::None};  // one permutation set per mode
  std::vector<Precision> precisions{Precision::Fp32};
  std::vector<Quality> qualities{Quality::High};
  std::vector<Target> targets{Target::Spirv};  // see compile/targets.hpp
  // "optimization": "O0" | "O1" | "O2"; `compile -O` overrides it (docs/scenes.md).
  OptimizationLevel optimization = OptimizationLevel::O2;
  std::vector<SceneMaterial> materials;
  std::vector<Diagnostic> warnings;
  SourceLocation lightsWhere, environmentWhere, precisionWhere, qualityWhere, targetsWhere;

  // Light types present, canonicalLights() order.
  std::vector<LightType> lightTypes() const;
};

// Picks the form by extension: .json (scene JSON, which may pull in a glTF file) or
// .gltf/.glb (a glTF scene with default axes). Material paths are relative to the scene file.
// Throws DiagnosticError with file:line:column for every problem found.
SceneDesc loadScene(const std::string& path, const ShaderLibrary& lib);
SceneDesc parseSceneJson(std::string text, const std::string& file, const ShaderLibrary& lib);

}  // namespace mb
