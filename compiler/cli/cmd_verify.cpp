// matbricks verify --scene FILE PACKAGE_DIR: does the package hold every permutation the
// scene requires? A missing one is an error with a diff, never a fallback to a similar
// variant (DESIGN.md "Permutation principles"; docs/scenes.md "Verify").
#include <cstdio>
#include <filesystem>

#include "cli/cli_common.hpp"
#include "core/json_fields.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"

namespace mb::cli {
namespace {

struct VerifyArgs {
  std::string scene;
  std::string package;
  bool quiet = false;
};

// "permutations"[i]["key"] of PACKAGE_DIR/manifest.json (docs/package.md).
std::vector<std::string> packageKeys(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / "manifest.json").string();
  JsonDocument doc = JsonDocument::load(path, input_kind::kManifest);
  DiagnosticSink sink;
  JsonFields f(doc, sink);
  std::vector<std::string> keys;
  if (f.isObject("") && !f.find("/permutations"))
    f.error("E-PACKAGE-MANIFEST", f.valueAt(""), "manifest has no 'permutations' array: not a matbricks package");
  if (f.find("/permutations") && f.isArray("/permutations"))
    for (size_t i = 0; i < f.find("/permutations")->size(); ++i) {
      std::string ptr = JsonFields::member(JsonFields::element("/permutations", i), "key");
      if (!f.find(ptr))
        f.error("E-PACKAGE-MANIFEST", f.valueAt(JsonFields::element("/permutations", i)), "permutation has no 'key'");
      else if (auto k = f.string(ptr))
        keys.push_back(*k);
    }
  sink.throwIfErrors();
  return keys;
}

int runVerify(const VerifyArgs& a, const GlobalOptions& g) {
  ShaderLibrary lib = loadLibrary(g);
  SceneDesc scene = loadScene(a.scene, lib);
  if (!scene.warnings.empty()) printDiagnostics(scene.warnings, g);
  ScenePlan plan = planScene(scene, lib);
  std::vector<std::string> required;
  for (const auto& p : plan.required) required.push_back(p.key());
  std::vector<std::string> present = packageKeys(a.package);
  std::string diff = diffKeys(required, present);
  if (diff.empty()) {
    if (!a.quiet)
      std::printf("package %s has all %zu permutations scene '%s' requires\n", a.package.c_str(), required.size(),
                  scene.name.c_str());
    return kExitOk;
  }
  size_t missing = 0;
  for (size_t i = 0; i < diff.size(); i = diff.find('\n', i) + 1) missing += diff[i] == '-';
  std::fprintf(
      stderr,
      "%s: error[E-PACKAGE-MISSING-PERMUTATION]: package %s lacks %zu of the %zu permutations scene '%s' requires (- required but missing, + present but not required)\n",
      a.scene.c_str(), a.package.c_str(), missing, required.size(), scene.name.c_str());
  std::fputs(diff.c_str(), stdout);
  return kExitCheckFailed;
}

}  // namespace

Command addVerifyCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand("verify", "Check that a package holds every permutation a scene requires");
  cmd->add_option("--scene", args->scene, kSceneFileHelp)->required();
  cmd->add_option("package", args->package, "Package directory (with manifest.json)")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  return {cmd, [args, &g] { return runVerify(*args, g); }};
}

}  // namespace mb::cli
