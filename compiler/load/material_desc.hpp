// A material, as every description form parses it (docs/formats.md): JSON, the macro form of
// seed 000, and glTF import all produce a MaterialSource (what the user wrote, with
// positions), which resolveMaterial checks against the library into one MaterialDesc.
// Emit, validate, stress and bench only ever see MaterialDesc.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "library/shader_library.hpp"
#include "load/engine_data.hpp"

namespace mb {

// User GLSL that computes the surface inputs from parameters, as Filament's material() or a
// Unity surface shader: it must define `void surface(inout MaterialInputs m, MaterialParams p)`.
// `where` is the file and line of the first line of `glsl`; the emitter puts a #line there, so
// a GLSL error is reported at the user's own file and line.
struct SurfaceCode {
  std::string glsl;
  SourceLocation where;
  bool present() const { return !glsl.empty(); }
};

// One parameter as the material sets it: a constant folded into the shader, or a run-time
// input with a default and a range (validation samples the range).
struct MaterialParam {
  std::string name;
  ValueType type = ValueType::Float;
  std::vector<double> value;  // the constant, or the default of an input
  bool constant = false;
  Range range;  // valid range of every component (inputs only)
  // A user parameter (not a model input): a member of MaterialParams, read only by the
  // surface code. Model inputs are members of MaterialInputs.
  bool user = false;
  SourceLocation where;
};

// ---------------------------------------------------------------------------------------
// What a description form produces: names as written, unchecked, with where each was written.
struct SourceName {
  std::string value;
  SourceLocation where;
};

struct SourceParam {
  std::string name;
  SourceLocation where;             // of the name
  std::optional<std::string> type;  // "float" | "vec2" | "vec3", as written (optional)
  SourceLocation typeWhere;
  std::vector<double> value;  // as written (1, 2 or 3 numbers)
  SourceLocation valueWhere;
  std::vector<SourceLocation> componentWhere;  // of each number of `value`, where the form knows
  std::optional<Range> range;                  // as written
  SourceLocation rangeWhere;
  bool constant = false;
  // The form already reported part of this parameter missing or malformed: resolveMaterial
  // checks what is there, reports nothing as missing, and drops the parameter.
  bool incomplete = false;
};

// Forms report what is missing or malformed in their own syntax (a JSON key, a #define) and
// leave it default-constructed here: resolveMaterial skips a name or model whose value and
// where.file are both empty instead of reporting it again.
struct MaterialSource {
  std::string file;  // the description's path (as given on the command line)
  std::string form;  // "json", "macro", "gltf"
  SourceName name;
  SourceName model;
  std::string description;
  std::vector<SourceName> features;
  std::vector<std::pair<SourceName, SourceName>> bricks;  // role -> brick id, as written
  SourceLocation bricksWhere;     // where a role without a brick is reported (default: model.where)
  bool bricksIncomplete = false;  // the form could not read every choice: report no role missing
  std::vector<std::pair<SourceName, SourceName>> lightMethods;  // light type -> method, as written
  std::vector<SourceParam> params;
  SurfaceCode surface;
  std::vector<Diagnostic> warnings;  // e.g. an unsupported glTF extension, reported by the CLI
  // What an engine needs to draw the material that the shader does not compute (glTF
  // materials only; load/engine_data.hpp). The package manifest carries it as "engine".
  std::optional<EngineData> engine;
  // Files read besides `file` (the macro form's #includes), in reading order: a build system
  // must rerun the compile when one changes (compile --depfile).
  std::vector<std::string> includedFiles;
};

// ---------------------------------------------------------------------------------------
struct MaterialDesc {
  std::string name;
  std::string model;
  std::string description;
  std::string form;                   // "json", "macro", "gltf"
  std::vector<std::string> features;  // enabled, in the model's feature order
  // role -> brick id for every role of the model whose feature (if any) is enabled,
  // light- and environment-conditional roles included; defaults filled in.
  std::map<std::string, std::string> bricks;
  // Model inputs (core and enabled features', in the model's order; those the material does
  // not set are constants at the model's default), then user parameters as declared.
  std::vector<MaterialParam> params;
  SurfaceCode surface;
  std::string sourceFile;
  std::vector<std::string> includedFiles;                // MaterialSource::includedFiles
  SourceLocation modelWhere;                             // where the model was named (invalid-axis errors point here)
  std::map<std::string, SourceLocation> brickLocations;  // role -> where it was chosen
  // Light type name -> method, for every light the model offers methods for (its
  // lightMethods); defaults filled in, then a quality level's choices (permute/specialize.hpp).
  std::map<std::string, std::string> lightMethods;
  std::map<std::string, SourceLocation> lightMethodLocations;  // light -> where the material chose it
  std::vector<Diagnostic> warnings;
  std::optional<EngineData> engine;  // MaterialSource::engine

  bool has(const std::string& feature) const;
  const MaterialParam* param(const std::string& name) const;
  // The method `light` is shaded by, or "" where the model offers no choice for it.
  std::string lightMethod(LightType light) const;
};

// Checks a MaterialSource against the library: model exists, features are the model's,
// every role filled with a brick of its slot (or its default), parameters typed and in
// range, user parameters only beside surface code. Collects every problem and throws
// DiagnosticError listing them in file order.
MaterialDesc resolveMaterial(const MaterialSource& source, const ShaderLibrary& lib);

// JSON form: reads and resolves. Throws DiagnosticError (file:line:column for every error).
MaterialDesc loadMaterialJson(const std::string& path, const ShaderLibrary& lib);
MaterialDesc parseMaterialJson(std::string text, const std::string& file, const ShaderLibrary& lib);
// Macro form (docs/macro-form.md).
MaterialDesc loadMaterialMacro(const std::string& path, const ShaderLibrary& lib);
MaterialDesc parseMaterialMacro(const std::string& text, const std::string& file, const ShaderLibrary& lib);
// Picks the form by extension: .json, .mat (macro form), .gltf/.glb (several materials).
std::vector<MaterialDesc> loadMaterialFile(const std::string& path, const ShaderLibrary& lib);

}  // namespace mb
