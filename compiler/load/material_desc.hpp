// A material, as parsed from JSON (and later the macro form). Both forms produce this.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "library/shader_library.hpp"

namespace mb {

// One model input as the material sets it: a constant folded into the shader, or a run-time
// input with a default and a range (validation samples the range).
struct MaterialParam {
  std::string name;
  ValueType type = ValueType::Float;
  std::vector<double> value;  // the constant, or the default of an input
  bool constant = false;
  Range range;                // valid range of every component (inputs only)
  SourceLocation where;
};

struct MaterialDesc {
  std::string name;
  std::string model;
  std::string description;
  std::map<std::string, std::string> bricks;  // slot -> brick id (every slot of the model)
  std::vector<MaterialParam> params;          // one per model input, in the model's order
  std::string sourceFile;
  std::map<std::string, SourceLocation> brickLocations;  // slot -> where it was chosen
};

// Reads a material JSON file and checks it against the library (model exists, every slot
// filled with a brick of that slot, parameters typed and in range). All problems are
// collected; throws DiagnosticError listing them (each with file:line:column).
MaterialDesc loadMaterialJson(const std::string& path, const ShaderLibrary& lib);
MaterialDesc parseMaterialJson(const std::string& text, const std::string& file,
                               const ShaderLibrary& lib);

}  // namespace mb
