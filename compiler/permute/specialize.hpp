// Specializing a material for one permutation: the quality level's bricks, and features the
// scene proves neutral folded away (docs/scenes.md "Folding"). The result is an ordinary
// MaterialDesc, so emit, compile and validate need no knowledge of either.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/quality.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "load/scene_desc.hpp"

namespace mb {

// The material's shading model; throws DiagnosticError (E-UNKNOWN-MODEL) when the library has
// none of that name.
const ShadingModel& modelOf(const MaterialDesc& material, const ShaderLibrary& lib);

// Roles the material left at the model default take the model's brick for `quality`
// (model manifest "quality" table); roles the material chose keep its choice. "high" is the
// default bindings. Throws DiagnosticError for a level the model does not define.
MaterialDesc applyQuality(const MaterialDesc& material, Quality quality, const ShaderLibrary& lib);

// Why `feature` of `material` cannot be folded over these uses, or nullopt when every use
// holds the feature's neutral input (ModelInput::neutral) at exactly its neutral value.
// Reasons: the feature has no neutral input; a use leaves a run-time input unstated; a use
// sets a non-neutral value; the surface code writes the input.
std::optional<std::string> foldBlocker(const MaterialDesc& material, const std::string& feature,
                                       const std::vector<MaterialUse>& uses, const ShaderLibrary& lib);

// The material without these features: not in `features`, their roles and inputs removed.
MaterialDesc foldFeatures(const MaterialDesc& material, const std::vector<std::string>& folded,
                          const ShaderLibrary& lib);

// The feature-complete ("uber") form used to check pruning: every feature of the model on.
// Inputs of features the material lacks (or folded) become constants at `use`'s value, or
// the input's neutral value, or its default; the other inputs keep the material's form.
// Pass the plan's specialized material (Permutation::material: folded, quality applied), not
// the loaded one: then a folded feature counts as lacking, and a kept one keeps its input.
MaterialDesc featureComplete(const MaterialDesc& material, const MaterialUse& use, const ShaderLibrary& lib);

}  // namespace mb
