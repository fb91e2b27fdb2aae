#include "driver/compile_request.hpp"

#include <algorithm>

#include "core/json_fields.hpp"
#include "core/optimization_level.hpp"
#include "core/package_stages.hpp"
#include "core/vocabulary.hpp"
#include "write/output_paths.hpp"

namespace mb {

void checkHeaderName(const std::string& name, const SourceLocation& at) {
  checkOutputName(name, "--header", at);
  std::vector<std::string> taken{"manifest.json", "include", "fragment"};
  for (const auto& t : allTargetNames()) taken.push_back(t);
  if (std::find(taken.begin(), taken.end(), name) != taken.end())
    throw DiagnosticError({{Severity::Error, "E-OUTPUT-NAME", at,
                            "--header '" + name + "' is a name the package itself writes at its top level",
                            "give another file name such as materials.hpp"}});
}

nlohmann::json compileRequestJson(const CompileRequest& r) {
  return {{"materials", r.materials},
          {"scene", r.scene},
          {"lights", lightTypeNames(r.lights)},
          {"environment", environmentModeName(r.environment)},
          {"precision", precisionName(r.precision)},
          {"quality", qualityName(r.quality)},
          {"targets", targetNames(r.targets)},
          {"header", r.headerName},
          {"namespace", r.cppNamespace},
          {"optimization", r.optimization},
          {"stages", r.stages},
          {"shaderlib", r.shaderlib}};
}

void compileRequestFromJson(const nlohmann::json& c, const std::string& file, CompileRequest& r) {
  auto notReadable = [&](const std::string& why) {
    return DiagnosticError({{Severity::Error,
                             "E-SHARD-NOT-SHARD",
                             {file, 0, 0},
                             "shard.json's 'command' is not readable: " + why,
                             "compile the shards again with this matbricks"}});
  };
  std::vector<std::string> lights, targets;
  std::string environment, precision, quality;
  try {
    r.materials = c.at("materials").get<std::vector<std::string>>();
    r.scene = c.at("scene").get<std::string>();
    lights = c.at("lights").get<std::vector<std::string>>();
    environment = c.at("environment").get<std::string>();
    precision = c.at("precision").get<std::string>();
    quality = c.at("quality").get<std::string>();
    targets = c.at("targets").get<std::vector<std::string>>();
    r.optimization = c.at("optimization").get<std::string>();
    r.stages = c.at("stages").get<std::string>();
    r.headerName = c.at("header").get<std::string>();
    r.cppNamespace = c.at("namespace").get<std::string>();
    r.shaderlib = c.at("shaderlib").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw notReadable(e.what());
  }
  // What the command line's CLI11 checks would have refused.
  OptimizationLevel level;
  if (!r.optimization.empty() && !parseOptimizationLevel(r.optimization, level))
    throw notReadable("'optimization' is not a level: '" + r.optimization + "'");
  PackageStages stages;
  if (std::string why; !r.stages.empty() && !parsePackageStages(r.stages, stages, why))
    throw notReadable("'stages': " + why);
  for (const auto& t : targets)
    if (!parseTarget(t)) throw notReadable("'targets': '" + t + "' is not a target");
  // An axis value the emitter (precision), the quality selection (quality) or the validity
  // rules (lights, environment) refused before the axes were types: the same code, now where the
  // shard is read.
  auto unknownAxisValue = [&](const std::string& code, const std::string& what, const std::string& value,
                              const std::vector<std::string>& names) {
    return DiagnosticError(
        {{Severity::Error, code, {file, 0, 0}, "unknown " + what + " '" + value + "'", "one of " + quotedList(names)}});
  };
  for (const auto& l : lights)
    if (!parseLightType(l)) throw unknownAxisValue("E-PERMUTATION-INVALID", "light type", l, allLightTypeNames());
  if (!parseEnvironmentMode(environment))
    throw unknownAxisValue("E-PERMUTATION-INVALID", "environment mode", environment, allEnvironmentModeNames());
  if (!parsePrecision(precision)) throw unknownAxisValue("E-PRECISION", "precision", precision, allPrecisionNames());
  if (!parseQuality(quality))
    throw unknownAxisValue("E-PERMUTATION-INVALID", "quality level", quality, allQualityNames());
  checkHeaderName(r.headerName, {file, 0, 0});
  r.lights = parseLightTypes(lights);
  r.environment = *parseEnvironmentMode(environment);
  r.precision = *parsePrecision(precision);
  r.quality = *parseQuality(quality);
  r.targets = parseTargets(targets);
}

}  // namespace mb
