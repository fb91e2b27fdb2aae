// The "uses" of a scene material: the values its inputs take where the scene uses it
// (docs/scenes.md "Uses"), checked against the loaded material and its model.
#pragma once
#include <string>
#include <vector>

#include "core/json_fields.hpp"
#include "load/scene_desc.hpp"

namespace mb {

// Reads the array at `ptr` (absent: one implicit use at the material's own values). Unknown
// input names (with a suggestion), values of the wrong arity or outside the input's range,
// and a value that contradicts one of the material's constants are reported into `f`'s sink.
std::vector<MaterialUse> readUses(JsonFields& f, const std::string& ptr, const MaterialDesc& material,
                                  const ShaderLibrary& lib);

// A use's value as the scene wrote it: "0.5" or "[0.0, 0.0, 0.0]", for messages.
std::string formatUseValue(const std::vector<double>& value);

}  // namespace mb
