// matbricks compile: materials (or a scene) -> the required permutations -> built in
// parallel through the cache, to every target -> a package written atomically
// (docs/cli.md, docs/scenes.md, docs/targets.md, docs/package.md).
#include <cstdio>
#include <iostream>
#include <map>
#include <thread>

#include "cli/cli_common.hpp"
#include "compile/build.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "write/depfile.hpp"
#include "write/package_contents.hpp"

namespace mb::cli {
namespace {

struct CompileArgs {
  std::vector<std::string> materials;
  std::string scene;
  std::string out;
  bool quiet = false;
  bool explain = false;
  std::vector<std::string> lights{"dir"};
  std::string environment = "none";
  std::string precision = "fp32";
  std::string quality = "high";
  std::vector<std::string> targets;  // empty: the scene's, else spirv
  unsigned jobs = 0;
  std::string cacheDir;
  bool noCache = false;
  std::string headerName = "matbricks_materials.hpp";
  std::string cppNamespace = "matbricks_materials";
  std::string depfile;
  CLI::Option* axisOptions[4] = {};
};

// Two materials of one name would write the same files: refuse rather than keep either.
void refuseDuplicateKeys(const std::vector<Permutation>& perms, const std::vector<const MaterialDesc*>& sources) {
  std::map<std::string, size_t> byKey;
  std::vector<Diagnostic> duplicates;
  for (size_t i = 0; i < perms.size(); ++i) {
    auto [it, fresh] = byKey.emplace(perms[i].key(), i);
    if (!fresh)
      duplicates.push_back({Severity::Error,
                            "E-DUPLICATE-MATERIAL",
                            {sources[i]->sourceFile, 1, 1},
                            "material '" + sources[i]->name + "' is also defined in " +
                                sources[it->second]->sourceFile + ": permutation '" + perms[i].key() +
                                "' would be written twice",
                            "rename one of them"});
  }
  if (!duplicates.empty()) throw DiagnosticError(duplicates);
}

// Before any compiling: -o must be new, empty or a package, and neither it nor the depfile may
// be, contain or lie inside what the compile reads or the cache (docs/cli.md "Outputs").
void refuseUnsafeOutputs(const CompileArgs& a, const ShaderLibrary& lib, const SceneDesc& scene,
                         const std::vector<MaterialDesc>& materials, const std::filesystem::path& cacheDir) {
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  std::vector<const MaterialDesc*> read;  // the files' materials, or the scene's
  for (const auto& m : materials) read.push_back(&m);
  for (const auto& m : scene.materials) read.push_back(&m.material);
  addMaterialInputs(inputs, read, a.scene);
  if (!cacheDir.empty()) inputs.push_back({cacheDir, "cache directory"});
  if (!a.out.empty()) checkDirectoryOutput(a.out, inputs);
  if (!a.depfile.empty()) {
    inputs.push_back({a.out, "output directory"});
    checkFileOutput(a.depfile, "depfile", inputs);
  }
}

int runCompile(const CompileArgs& a, const GlobalOptions& g) {
  // Usage errors exit 2 (CLI::ValidationError), as CLI11's own do.
  if (a.scene.empty() == a.materials.empty())
    throw CLI::ValidationError("compile takes either MATERIAL files or --scene FILE, not both or neither");
  if (!a.scene.empty())
    for (const CLI::Option* o : a.axisOptions)
      if (o && o->count() > 0)
        throw CLI::ValidationError(o->get_name() +
                                   " conflicts with --scene: the scene file sets that axis (docs/scenes.md)");
  if (a.out.empty() && !a.explain) throw CLI::ValidationError("compile needs -o DIR (or --explain, which only counts)");
  if (!a.depfile.empty() && a.out.empty())
    throw CLI::ValidationError("--depfile needs -o DIR (its target is DIR/manifest.json)");

  ShaderLibrary lib = loadLibrary(g);
  SceneDesc scene;
  std::vector<MaterialDesc> materials;
  ScenePlan plan;
  std::vector<std::string> targets = a.targets;
  if (!a.scene.empty()) {
    scene = loadScene(a.scene, lib);
    if (!scene.warnings.empty()) printDiagnostics(scene.warnings, g);
    plan = planScene(scene, lib);
    if (targets.empty()) targets = scene.targets;
  } else {
    materials = loadMaterials(a.materials, lib, g);
    AxisPoint axes;
    axes.lights = canonicalLights(a.lights);
    axes.environment = a.environment;
    axes.precision = a.precision;
    axes.quality = a.quality;
    plan = planMaterials(materials, axes, lib);
    std::vector<const MaterialDesc*> sources;
    for (const auto& p : plan.required) sources.push_back(p.material);
    refuseDuplicateKeys(plan.required, sources);
  }
  if (targets.empty()) targets = {"spirv"};

  BuildOptions options;
  options.jobs = a.jobs;
  options.targets = targets;
  options.cacheDir = a.noCache ? std::filesystem::path()
                               : (a.cacheDir.empty() ? ShaderCache::defaultDir() : std::filesystem::path(a.cacheDir));
  refuseUnsafeOutputs(a, lib, scene, materials, options.cacheDir);
  BuildStats stats;
  std::vector<BuiltPermutation> built = buildPermutations(lib, plan.required, options, &stats);

  if (!a.quiet && !a.explain)
    for (const auto& b : built)
      std::printf("compiled %-52s %7.2f ms  %5zu instructions  %s%s\n", b.shader.key.c_str(), b.compileMs,
                  spirvInstructionCount(b.artifacts.spirv), b.spirvHash.c_str(), b.fromCache ? "  (cached)" : "");
  if (a.explain) {
    // Every required permutation is in `built`; say how many glslang built now and how many
    // the cache or an identical emitted GLSL supplied.
    const size_t sharedGlsl = stats.permutations - stats.compiled - stats.cacheHits;
    std::string how = std::to_string(stats.compiled) + " built now, " + std::to_string(stats.cacheHits) +
                      " from the cache" +
                      (sharedGlsl ? ", " + std::to_string(sharedGlsl) + " sharing another's identical GLSL" : "");
    std::fputs(explainText(plan, built.size(), stats.uniqueSpirv, how).c_str(), stdout);
  }

  if (!a.out.empty()) {
    PackageWriter pkg;
    PackageInputs in;
    in.lib = &lib;
    in.plan = &plan;
    in.built = &built;
    in.targets = targets;
    in.sceneFile = a.scene;
    in.headerName = a.headerName;
    in.cppNamespace = a.cppNamespace;
    addPackageFiles(pkg, in);
    pkg.commit(a.out);
  }
  if (!a.depfile.empty()) {
    // After the package, so a failed compile leaves the previous depfile with its package.
    const std::string absTarget =
        std::filesystem::absolute(std::filesystem::path(a.out) / "manifest.json").lexically_normal().generic_string();
    PackageWriter::writeFileAtomically(a.depfile,
                                       makeDepfile(absTarget, compileInputs(lib, plan.required, built, {a.scene})));
  }
  if (!a.quiet)
    std::printf("%s %zu permutation(s) (%zu unique SPIR-V, %zu compiled, %zu cached%s) in %.0f ms with %u job(s)%s\n",
                a.out.empty() ? "built" : "wrote", built.size(), stats.uniqueSpirv, stats.compiled, stats.cacheHits,
                stats.cacheCorrupt
                    ? (", " + std::to_string(stats.cacheCorrupt) + " corrupt cache entries rebuilt").c_str()
                    : "",
                stats.wallMs, options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency()),
                a.out.empty() ? "" : (" to " + a.out).c_str());
  return kExitOk;
}

}  // namespace

Command addCompileCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "Compile materials, or exactly what a scene needs, into a package");
  cmd->add_option("materials", args->materials, kMaterialFilesHelp);
  cmd->add_option("--scene", args->scene, std::string(kSceneFileHelp) + "; compile exactly the permutations it needs");
  cmd->add_option(
      "-o,--output", args->out,
      "Package directory: created, filled when empty, or replaced atomically when it is a matbricks package; "
      "anything else is refused");
  cmd->add_flag("--explain", args->explain,
                "Print possible / required / compiled / unique counts and which axis multiplied them");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  args->axisOptions[0] =
      cmd->add_option("--lights", args->lights, "Light types every permutation shades (default: dir)")
          ->delimiter(',')
          ->check(CLI::IsMember(allLightTypes()));
  args->axisOptions[1] = cmd->add_option("--environment", args->environment, "Environment mode (default: none)")
                             ->check(CLI::IsMember(allEnvironmentModes()));
  args->axisOptions[2] =
      cmd->add_option("--precision", args->precision, "fp32 or fp16")->check(CLI::IsMember(allPrecisions()));
  args->axisOptions[3] = cmd->add_option("--quality", args->quality, "low, medium or high (default: high)")
                             ->check(CLI::IsMember(allQualityLevels()));
  cmd->add_option(
         "--targets", args->targets,
         "Output languages (default: the scene's, else spirv): " +
             [] {
               std::string s;
               for (const auto& t : allTargets()) s += (s.empty() ? "" : ",") + t;
               return s;
             }())
      ->delimiter(',')
      ->check(CLI::IsMember(allTargets()));
  cmd->add_option("-j,--jobs", args->jobs,
                  "Parallel compile jobs (default: every core); output is identical at every -j");
  cmd->add_option(
      "--cache-dir", args->cacheDir,
      "Compile cache directory (default: $MATBRICKS_CACHE_DIR, $XDG_CACHE_HOME/matbricks or ~/.cache/matbricks)");
  cmd->add_flag("--no-cache", args->noCache, "Neither read nor write the compile cache");
  cmd->add_option("--header", args->headerName, "Name of the generated C++ header (default: matbricks_materials.hpp)");
  cmd->add_option("--namespace", args->cppNamespace,
                  "C++ namespace of the generated header (default: matbricks_materials)");
  cmd->add_option(
      "--depfile", args->depfile,
      "Also write every file the compile read, in Makefile syntax, with the package's manifest.json as target");
  return {cmd, [args, &g] { return runCompile(*args, g); }};
}

}  // namespace mb::cli
